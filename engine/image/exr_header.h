#pragma once
// A guard in front of OpenEXR for files a user hands the workbench: OpenEXR
// allocates each header attribute at the size the file claims before it
// finds the file too short, so a 1.3 KB file whose `comments` attribute
// claims 1.9 GB took 5 s and 2 GB of memory to refuse (found by fuzz_image).
// The header is walked here first, as OpenEXR reads it: by names, types and
// sizes, and by the values whose reading does not follow their size (most
// types are read at their own size whatever the field says, a channel list
// up to its empty name), so that the walk and OpenEXR stay at one place.

#include <filesystem>
#include <string>

namespace sdfwb::image {

// "" when `path` is not an OpenEXR file (no magic number) or every attribute
// of its headers fits in the file and is read by OpenEXR at its stated size;
// otherwise what is wrong (the attribute's name quoted: it is the file's
// bytes), for example
// "its OpenEXR header attribute \"comments\" claims 1929380159 bytes, past the
// file's end (1269 bytes)".
std::string exrHeaderProblem(const std::filesystem::path& path);

}  // namespace sdfwb::image
