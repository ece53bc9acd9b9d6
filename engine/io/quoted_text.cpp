#include "io/quoted_text.h"

namespace sdfwb::io {

std::string escapedExcerpt(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    const std::size_t shown = text.size() > kMaxQuotedCharacters ? kMaxQuotedCharacters : text.size();
    for (std::size_t i = 0; i < shown; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c < 0x20 || c >= 0x7f) {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    if (shown < text.size()) {
        out += "... (" + std::to_string(text.size()) + " bytes)";
    }
    return out;
}

std::string quoted(std::string_view text) { return "\"" + escapedExcerpt(text) + "\""; }

}  // namespace sdfwb::io
