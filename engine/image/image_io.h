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

// What a file's pixels hold. Colour: 8- and 16-bit pixels store the display
// encoding and are decoded from sRGB to linear; floats are linear already.
// Data (a bump map's heights): every pixel is taken as stored, 8- and 16-bit
// ones as their fraction of the largest value, as painting programs and
// renderers treat height maps (a grey of 128 is half way up, not 0.22).
enum class PixelValues { Colour, Data };

// Reads any image OpenImageIO can read as RGB (a one- or two-channel image is
// grey). Throws std::runtime_error naming the path, also for an image of more
// than `maxPixels` pixels (checked before its pixels are read).
Image readImage(const std::filesystem::path& path, std::size_t maxPixels = std::size_t(1) << 28,
                PixelValues values = PixelValues::Colour);

// Whether the file stores the display encoding (8-bit) rather than linear floats.
bool isDisplayEncoded(const std::filesystem::path& path);

}  // namespace sdfwb::image
