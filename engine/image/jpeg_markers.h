#pragma once
// A guard in front of OpenImageIO's JPEG reader for files a user hands the
// workbench: it decodes the IPTC block of a Photoshop APP13 segment
// (OpenImageIO 2.4, decode_iptc_iim) trusting the sizes the block claims,
// and a record claiming more bytes than its block holds was read past the
// end of the segment (a heap-buffer-overflow under AddressSanitizer, found
// by fuzz_image). The block is walked here first, as that reader walks it.

#include <filesystem>
#include <string>

namespace sdfwb::image {

// "" when `path` is not a JPEG file (no start-of-image marker) or its IPTC
// block's sizes hold; otherwise what is wrong, for example "its JPEG IPTC
// record claims 1200 bytes, past the end of its block (300 bytes)".
std::string jpegMarkerProblem(const std::filesystem::path& path);

}  // namespace sdfwb::image
