#include "image/exr_header.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <vector>

#include "io/quoted_text.h"

namespace sdfwb::image {
namespace {

constexpr std::uint32_t kMagic = 20000630;        // 0x762f3101, little endian
constexpr std::uint32_t kMultipartFlag = 0x1000;  // in the version field: headers follow each other
// The longest name OpenEXR reads, of an attribute, a type or a channel
// (Imf::Name::MAX_LENGTH, whatever the version field's long-names flag says).
// It refuses a longer one itself, without allocating.
constexpr std::size_t kMaxName = 255;
// After its name, a channel is a pixel type, a linear flag, 3 bytes of
// padding and two sampling rates.
constexpr std::size_t kChannelFieldBytes = 16;

// OpenEXR reads the value of most types it knows at the type's own size,
// whatever the attribute's size field says; a field that says otherwise
// puts OpenEXR and a walk by sizes at different places in the file. The
// next thing OpenEXR read in one such file was a string of 1.9 GB. These
// types must say their own size.
struct FixedSizeType {
    std::string_view name;
    std::uint32_t bytes;
};
constexpr std::array kFixedSizeTypes = {
    FixedSizeType{"box2i", 16},
    FixedSizeType{"box2f", 16},
    FixedSizeType{"chromaticities", 32},
    FixedSizeType{"compression", 1},
    FixedSizeType{"deepImageState", 1},
    FixedSizeType{"double", 8},
    FixedSizeType{"envmap", 1},
    FixedSizeType{"float", 4},
    FixedSizeType{"int", 4},
    FixedSizeType{"keycode", 28},
    FixedSizeType{"lineOrder", 1},
    FixedSizeType{"m33d", 72},
    FixedSizeType{"m33f", 36},
    FixedSizeType{"m44d", 128},
    FixedSizeType{"m44f", 64},
    FixedSizeType{"rational", 8},
    FixedSizeType{"tiledesc", 9},
    FixedSizeType{"timecode", 8},
    FixedSizeType{"v2d", 16},
    FixedSizeType{"v2f", 8},
    FixedSizeType{"v2i", 8},
    FixedSizeType{"v3d", 24},
    FixedSizeType{"v3f", 12},
    FixedSizeType{"v3i", 12},
};

std::uint32_t littleEndian32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

enum class NameRead { Read, TooLong, CutShort };

// A NUL-terminated string of at most kMaxName bytes.
NameRead readName(std::istream& in, std::string& name) {
    name.clear();
    for (char c; in.get(c);) {
        if (c == '\0') return NameRead::Read;
        if (name.size() == kMaxName) return NameRead::TooLong;
        name.push_back(c);
    }
    return NameRead::CutShort;
}

// OpenEXR reads a channel list up to the empty name that ends it; it must
// end exactly where the attribute's size says.
bool channelListFills(const std::vector<unsigned char>& value) {
    for (std::size_t at = 0; at < value.size();) {
        std::size_t length = 0;
        while (at + length < value.size() && value[at + length] != 0) ++length;
        if (at + length == value.size() || length > kMaxName) return false;
        if (length == 0) return at + 1 == value.size();
        at += length + 1 + kChannelFieldBytes;
    }
    return false;
}

// OpenEXR reads strings, each after its length, while it has read less than
// the size; they must fill it exactly.
bool stringVectorFills(const std::vector<unsigned char>& value) {
    std::size_t at = 0;
    while (at < value.size()) {
        if (value.size() - at < 4) return false;
        const std::uint32_t length = littleEndian32(value.data() + at);
        at += 4;
        if (length > value.size() - at) return false;
        at += length;
    }
    return true;
}

// Moves `in` past the value of an attribute of `type` and `bytes`, and says
// why OpenEXR would read other than those bytes there ("" when it would not).
std::string valueProblem(std::string_view type, std::uint32_t bytes, std::istream& in) {
    for (const FixedSizeType& fixed : kFixedSizeTypes) {
        if (type == fixed.name && bytes != fixed.bytes) {
            return "claims " + std::to_string(bytes) + " bytes for a " + std::string(type) +
                   ", which OpenEXR reads as " + std::to_string(fixed.bytes);
        }
    }
    if (type == "preview") {
        // a width and a height, then 4 bytes a pixel: OpenEXR allocates the
        // pixels before it reads them
        unsigned char dimensions[8];
        if (bytes < 8 || !in.read(reinterpret_cast<char*>(dimensions), 8)) {
            return "holds a preview of " + std::to_string(bytes) + " bytes";
        }
        const std::uint64_t pixels = std::uint64_t(littleEndian32(dimensions)) * littleEndian32(dimensions + 4);
        if ((bytes - 8) % 4 != 0 || pixels != (bytes - 8) / 4) {
            return "holds a preview whose size disagrees with its width and height";
        }
        in.seekg(static_cast<std::streamoff>(bytes - 8), std::ios::cur);
        return "";
    }
    // OpenEXR 3.1 reads an ID manifest 4 bytes past its size; textures need none
    if (type == "idmanifest") return "is an ID manifest, which OpenEXR 3.1 reads past its size";
    if (type == "floatvector" && bytes % 4 != 0) return "holds a floatvector of " + std::to_string(bytes) + " bytes";
    if (type != "chlist" && type != "stringvector") {
        in.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
        return "";
    }
    std::vector<unsigned char> value(bytes);
    if (!in.read(reinterpret_cast<char*>(value.data()), static_cast<std::streamsize>(bytes))) return "is cut short";
    const bool fills = type == "chlist" ? channelListFills(value) : stringVectorFills(value);
    return fills ? "" : "does not end where its size (" + std::to_string(bytes) + " bytes) says";
}

}  // namespace

std::string exrHeaderProblem(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t fileSize = std::filesystem::file_size(path, error);
    std::ifstream in(path, std::ios::binary);
    unsigned char start[8];
    if (error || !in.read(reinterpret_cast<char*>(start), 8) || littleEndian32(start) != kMagic) return "";
    const bool multipart = (littleEndian32(start + 4) & kMultipartFlag) != 0;
    const std::string tooShort = "its OpenEXR header is cut short";
    const std::string tooLong =
        "its OpenEXR header has an attribute name or type longer than " + std::to_string(kMaxName) + " bytes";
    auto attribute = [](const std::string& name) { return "its OpenEXR header attribute " + io::quoted(name); };
    std::string name, type;
    // each step reads at least one byte of the file, so the walk ends
    for (bool headerStart = true;;) {
        if (NameRead read = readName(in, name); read != NameRead::Read) {
            return read == NameRead::TooLong ? tooLong : tooShort;
        }
        if (name.empty()) {
            // the end of a header; a multipart file ends its headers with an empty one
            if (!multipart || headerStart) return "";
            headerStart = true;
            continue;
        }
        headerStart = false;
        unsigned char size[4];
        if (NameRead read = readName(in, type); read != NameRead::Read) {
            return read == NameRead::TooLong ? tooLong : tooShort;
        }
        if (!in.read(reinterpret_cast<char*>(size), 4)) return tooShort;
        const std::uint32_t bytes = littleEndian32(size);
        const std::uintmax_t position = static_cast<std::uintmax_t>(in.tellg());
        if (bytes > 0x7fffffffu || bytes > fileSize - position) {
            return attribute(name) + " claims " + std::to_string(static_cast<std::int32_t>(bytes)) +
                   " bytes, past the file's end (" + std::to_string(fileSize) + " bytes)";
        }
        if (std::string problem = valueProblem(type, bytes, in); !problem.empty()) {
            return attribute(name) + " " + problem;
        }
    }
}

}  // namespace sdfwb::image
