#include "scene/json_text.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "io/quoted_text.h"

namespace sdfwb::scene {
namespace {

using json = nlohmann::ordered_json;

std::string lineColumn(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann's reason without its "[json.exception...]" and position prefixes and
// without the raw token it quotes (which can be megabytes long).
std::string reasonOf(const nlohmann::json::exception& error) {
    std::string what = error.what();
    std::size_t start = what.find("] ");
    start = start == std::string::npos ? 0 : start + 2;
    std::size_t colon = what.find(": ", start);
    if (what.compare(start, 11, "parse error") == 0 && colon != std::string::npos) {
        start = colon + 2;
    }
    std::string reason = what.substr(start);
    std::size_t lastRead = reason.find("; last read: ");
    if (lastRead != std::string::npos) {
        reason.erase(lastRead);
    }
    std::size_t parsing = reason.find(" parsing '");
    if (parsing != std::string::npos) {
        reason.erase(parsing);  // "number overflow parsing '1e999'": the token is added by the caller
    }
    return reason;
}

// Checks structure while nlohmann's parser reads; builds nothing.
class StructureCheck {
public:
    explicit StructureCheck(std::string_view text) : text_(text) {}

    std::string problem;

    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(json::number_integer_t) { return value(); }
    bool number_unsigned(json::number_unsigned_t) { return value(); }
    bool number_float(json::number_float_t, const json::string_t&) { return value(); }
    bool string(json::string_t&) { return value(); }
    bool binary(json::binary_t&) { return value(); }

    bool start_object(std::size_t) { return open(true); }
    bool end_object() { return close(); }
    bool start_array(std::size_t) { return open(false); }
    bool end_array() { return close(); }

    bool key(json::string_t& name) {
        Frame& frame = frames_.back();
        frame.key = name;
        frame.hasKey = true;
        if (!frame.keys.insert(name).second) {
            return fail(abbreviatedPath(path()) + ": duplicate key " + io::quoted(name) +
                        " (each field may be given once)");
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const nlohmann::json::exception& error) {
        // position is just past the offending character; a number that
        // overflows is named where it starts
        std::size_t offset = position == 0 ? 0 : position - 1;
        std::string message;
        if (error.id == 406) {
            offset = position >= lastToken.size() ? position - lastToken.size() : 0;
            message = ": invalid JSON: " + reasonOf(error) + " " + io::quoted(lastToken) + " (numbers must be finite)";
        } else {
            message = ": invalid JSON: " + reasonOf(error);
        }
        message = lineColumn(text_, offset) + message;
        return fail(message);
    }

private:
    struct Frame {
        bool object = false;
        std::size_t nextIndex = 0;  // arrays: the index of the next element
        bool hasKey = false;
        std::string key;            // objects: the current member
        std::unordered_set<std::string> keys;
    };

    bool fail(std::string message) {
        if (problem.empty()) {
            problem = std::move(message);
        }
        return false;
    }

    // A value starts: arrays count their elements for the path.
    bool value() {
        if (!frames_.empty() && !frames_.back().object) {
            ++frames_.back().nextIndex;
        }
        return true;
    }

    bool open(bool object) {
        value();
        if (frames_.size() >= kMaxJsonDepth) {
            return fail(abbreviatedPath(path()) + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                        " levels of arrays and objects");
        }
        frames_.push_back(Frame{object, 0, false, {}, {}});
        return true;
    }

    bool close() {
        frames_.pop_back();
        return true;
    }

    // The path of the value being read, in the scene reader's notation.
    std::string path() const {
        std::string out;
        for (const Frame& frame : frames_) {
            if (frame.object) {
                if (frame.hasKey) {
                    out += (out.empty() ? "" : ".") + io::escapedExcerpt(frame.key);
                }
            } else if (frame.nextIndex > 0) {
                out += "[" + std::to_string(frame.nextIndex - 1) + "]";
            }
        }
        return out.empty() ? "(top level)" : out;
    }

    std::string_view text_;
    std::vector<Frame> frames_;
};

}  // namespace

std::string abbreviatedPath(std::string_view path) {
    constexpr std::size_t kHead = 40, kTail = 100;
    if (path.size() <= kHead + kTail + 5) {
        return std::string(path);
    }
    return std::string(path.substr(0, kHead)) + " ... " + std::string(path.substr(path.size() - kTail));
}

json parseStrictJson(std::string_view text) {
    std::size_t nul = text.find('\0');
    if (nul != std::string_view::npos) {
        throw JsonTextError(lineColumn(text, nul) + ": invalid JSON: a NUL byte (a scene file is UTF-8 text)");
    }
    StructureCheck check(text);
    if (!json::sax_parse(text.begin(), text.end(), &check)) {
        throw JsonTextError(check.problem.empty() ? "invalid JSON" : check.problem);
    }
    return json::parse(text.begin(), text.end());
}

}  // namespace sdfwb::scene
