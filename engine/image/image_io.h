#pragma once
// Reading and writing images through OpenImageIO. 8-bit formats (png, jpg, tif)
// store the display encoding (encoding.h); exr stores linear float.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "io/atomic_file.h"

namespace sdfwb::image {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Throws std::runtime_error with one line naming the problem when the extension
// is not one of .png .jpg .jpeg .tif .tiff .exr.
void checkWritableFormat(const std::filesystem::path& path);

// Writes atomically (temporary sibling + rename): on failure nothing is left at
// `path`. Metadata entries become image attributes (e.g. "sdfwb:backend").
// Throws std::runtime_error naming the path and the cause.
void writeImage(const std::filesystem::path& path, const Image& image, const Metadata& metadata = {});
// writeImage's first half: the image is written and checked, and replaces
// `path` when `writes` is committed (with the other files staged there).
void stageImage(io::StagedWrites& writes, const std::filesystem::path& path, const Image& image,
                const Metadata& metadata = {});

// Reads any image OpenImageIO can read as linear RGB (8-bit data is decoded
// from sRGB; a one- or two-channel image is grey). Throws std::runtime_error
// naming the path, also for an image of more than `maxPixels` pixels (checked
// before its pixels are read).
Image readImage(const std::filesystem::path& path, std::size_t maxPixels = std::size_t(1) << 28);

// Whether the file stores the display encoding (8-bit) rather than linear floats.
bool isDisplayEncoded(const std::filesystem::path& path);

}  // namespace sdfwb::image
