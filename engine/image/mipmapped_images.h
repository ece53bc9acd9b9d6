#pragma once
// Images as the shared sampler reads them (sdf/glsl/mipmap_lookup.glsl): an
// environment map's (lecture notes on realism, 1.5) or a material's texture
// (1.1), each resampled once to a square of side N = 2^n, rows from the
// bottom, with its mipmaps (image/mipmaps.h), image after image in one texel
// array that the GL backend uploads as a buffer texture and the CPU backend
// reads directly.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "image/image.h"
#include "image/image_io.h"

namespace sdfwb::image {

struct MipmappedImages {
    int side = 0;    // N, the same for every image
    int levels = 0;  // n + 1
    std::vector<glm::vec4> texels;
};

// N is the least power of two at least every image's width and height, at
// most this: 1024 for a single image (22 MB of texels with its mipmaps),
// 512 for each of a box map's six faces (34 MB) and for a texture (6 MB).
inline constexpr int kMaxEnvironmentSide = 1024;
inline constexpr int kMaxBoxFaceSide = 512;
inline constexpr int kMaxTextureSide = 512;
// Files larger than this many pixels are refused before they are read. A
// fuzz build (libFuzzer's convention, as kMaxExpansionWork in
// expr/fractions.h) refuses past 256 x 256: a 60-byte file may claim 4096 x
// 4096, and OpenImageIO clears a buffer of that size before it finds the data
// missing (256 MB; about 30 inputs a second under ASan, where the fuzzer
// should be exploring the readers, not the clearing).
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
inline constexpr std::size_t kMaxImageFilePixels = std::size_t(1) << 16;
#else
inline constexpr std::size_t kMaxImageFilePixels = std::size_t(1) << 24;
#endif
// Texel values are clamped to [0, this]; NaN becomes 0 (a few bad pixels in
// an HDR file must not turn the whole frame non-finite).
inline constexpr float kMaxTexelValue = 1e9f;

// Reads and converts the images (colour: 8- and 16-bit files decoded from
// sRGB to linear; data: as stored, image_io.h).
// Throws std::runtime_error "cannot read image PATH: reason".
MipmappedImages loadMipmappedImages(const std::vector<std::filesystem::path>& files, int maxSide,
                                    PixelValues values = PixelValues::Colour);

// loadMipmappedImages through a small cache keyed by the files' paths,
// sizes and modification times (and how their pixels are read), so rendering
// a scene again (every edit) does not read its images again; failures are
// cached as well and thrown again. Thread-safe.
std::shared_ptr<const MipmappedImages> cachedMipmappedImages(const std::vector<std::filesystem::path>& files,
                                                             int maxSide, PixelValues values = PixelValues::Colour);

// Image `index` of `images` at its largest mip level of side at most
// `maxSide` (at least 1 x 1), rows from the top: a thumbnail for the editor.
Image mipmapPreview(const MipmappedImages& images, int index, int maxSide);

// What a map or texture shows when its images cannot be read (the editor
// still opens the scene): a magenta and black checkerboard, `count` images of
// side 8.
std::shared_ptr<const MipmappedImages> placeholderImages(int count);

}  // namespace sdfwb::image
