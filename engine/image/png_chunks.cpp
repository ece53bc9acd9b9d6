#include "image/png_chunks.h"

#include <algorithm>
#include <cstdint>
#include <fstream>

#include "io/quoted_text.h"

namespace sdfwb::image {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::uintmax_t kChunkFraming = 12;  // length, type and CRC around the data

std::uint32_t bigEndian32(const unsigned char* b) {
    return std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | std::uint32_t(b[3]);
}

}  // namespace

std::string pngChunkProblem(const std::filesystem::path& path) {
    std::error_code error;
    const std::uintmax_t fileSize = std::filesystem::file_size(path, error);
    std::ifstream in(path, std::ios::binary);
    unsigned char start[8];
    if (error || !in.read(reinterpret_cast<char*>(start), 8) || !std::equal(start, start + 8, kSignature)) return "";
    // each chunk takes at least 12 bytes of the file, so the walk ends
    for (std::uintmax_t position = 8;;) {
        unsigned char header[8];
        // a file cut inside its chunks is libpng's to refuse: it allocates nothing for what is missing
        if (!in.read(reinterpret_cast<char*>(header), 8)) return "";
        const std::uint32_t length = bigEndian32(header);
        const std::string type(reinterpret_cast<const char*>(header + 4), 4);
        if (std::uintmax_t(length) + kChunkFraming > fileSize - position) {
            return "its PNG chunk " + io::quoted(type) + " claims " + std::to_string(length) +
                   " bytes, past the file's end (" + std::to_string(fileSize) + " bytes)";
        }
        if (type == "IEND") return "";
        position += kChunkFraming + length;
        in.seekg(static_cast<std::streamoff>(position));
    }
}

}  // namespace sdfwb::image
