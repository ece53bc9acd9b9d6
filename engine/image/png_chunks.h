#pragma once
// A guard in front of libpng for files a user hands the workbench: libpng
// allocates an ancillary chunk (tEXt, iCCP...) at the length the file claims
// before it finds the file too short, so an 838-byte PNG whose tEXt chunk
// claims 1.6 GB took that much memory to refuse (found by fuzz_image). The
// chunks are walked here first, reading nothing but lengths and types.

#include <filesystem>
#include <string>

namespace sdfwb::image {

// "" when `path` is not a PNG file (no signature) or every chunk up to IEND
// fits in the file; otherwise what is wrong (the chunk's type quoted: it is
// the file's bytes), for example "its PNG chunk \"tEXt\" claims 1634861387
// bytes, past the file's end (837 bytes)".
std::string pngChunkProblem(const std::filesystem::path& path);

}  // namespace sdfwb::image
