#include "image/exr_header.h"

#include <cstdint>
#include <fstream>

#include "io/quoted_text.h"

namespace sdfwb::image {
namespace {

constexpr std::uint32_t kMagic = 20000630;        // 0x762f3101, little endian
constexpr std::uint32_t kMultipartFlag = 0x1000;  // in the version field: headers follow each other
constexpr std::uint32_t kLongNamesFlag = 0x400;   // in the version field: names of up to 255 bytes
// The longest attribute name or type OpenEXR reads (Imf::Header::readFrom).
// It stops reading a name there whether or not its NUL has come, and reads
// the rest as the next field: a 1.6 KB file whose name ran on read a string
// attribute of 1.9 GB. Such a name makes the file unreadable here.
constexpr std::size_t kMaxShortName = 31;
constexpr std::size_t kMaxLongName = 255;

std::uint32_t littleEndian32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

enum class NameRead { Read, TooLong, CutShort };

// A NUL-terminated string of at most `longest` bytes.
NameRead readName(std::istream& in, std::size_t longest, std::string& name) {
    name.clear();
    for (char c; in.get(c);) {
        if (c == '\0') return NameRead::Read;
        if (name.size() == longest) return NameRead::TooLong;
        name.push_back(c);
    }
    return NameRead::CutShort;
}

}  // namespace

std::string exrHeaderProblem(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t fileSize = std::filesystem::file_size(path, error);
    std::ifstream in(path, std::ios::binary);
    unsigned char start[8];
    if (error || !in.read(reinterpret_cast<char*>(start), 8) || littleEndian32(start) != kMagic) return "";
    const bool multipart = (littleEndian32(start + 4) & kMultipartFlag) != 0;
    const std::size_t longest = (littleEndian32(start + 4) & kLongNamesFlag) != 0 ? kMaxLongName : kMaxShortName;
    const std::string tooShort = "its OpenEXR header is cut short";
    const std::string tooLong =
        "its OpenEXR header has an attribute name or type longer than " + std::to_string(longest) + " bytes";
    std::string name, type;
    // each attribute takes at least 6 bytes of the file, so the walk ends
    for (bool headerStart = true;;) {
        if (NameRead read = readName(in, longest, name); read != NameRead::Read) {
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
        if (NameRead read = readName(in, longest, type); read != NameRead::Read) {
            return read == NameRead::TooLong ? tooLong : tooShort;
        }
        if (!in.read(reinterpret_cast<char*>(size), 4)) return tooShort;
        const std::uint32_t bytes = littleEndian32(size);
        const std::uintmax_t position = static_cast<std::uintmax_t>(in.tellg());
        if (bytes > 0x7fffffffu || bytes > fileSize - position) {
            return "its OpenEXR header attribute " + io::quoted(name) + " claims " +
                   std::to_string(static_cast<std::int32_t>(bytes)) + " bytes, past the file's end (" +
                   std::to_string(fileSize) + " bytes)";
        }
        in.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
    }
}

}  // namespace sdfwb::image
