#pragma once
// The images of an environment map (lecture notes on realism, 1.5) as the
// shared sampler reads them (sdf/glsl/environment_lookup.glsl): each image
// resampled once to a square of side N = 2^n, rows from the bottom, with its
// mipmaps (image/mipmaps.h), image after image in one texel array that the GL
// backend uploads as a buffer texture and the CPU backend reads directly.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

namespace sdfwb::image {

struct EnvironmentImages {
    int side = 0;    // N, the same for every image
    int levels = 0;  // n + 1
    std::vector<glm::vec4> texels;
};

// N is the least power of two at least every image's width and height, at
// most this: 1024 for a single image (22 MB of texels with its mipmaps),
// 512 for each of a box map's six faces (34 MB).
inline constexpr int kMaxEnvironmentSide = 1024;
inline constexpr int kMaxBoxFaceSide = 512;
// Files larger than this many pixels are refused before they are read.
inline constexpr std::size_t kMaxEnvironmentFilePixels = std::size_t(1) << 24;
// Texel values are clamped to [0, this]; NaN becomes 0 (a few bad pixels in
// an HDR file must not turn the whole frame non-finite).
inline constexpr float kMaxEnvironmentRadiance = 1e9f;

// Reads and converts the images (8-bit files decoded from sRGB to linear).
// Throws std::runtime_error "cannot read image PATH: reason".
EnvironmentImages loadEnvironmentImages(const std::vector<std::filesystem::path>& files, int maxSide);

// loadEnvironmentImages through a small cache keyed by the files' paths,
// sizes and modification times, so rendering a scene again (every edit) does
// not read its images again; failures are cached as well and thrown again.
// Thread-safe.
std::shared_ptr<const EnvironmentImages> cachedEnvironmentImages(const std::vector<std::filesystem::path>& files,
                                                                 int maxSide);

// What a map shows when its images cannot be read (the editor still opens
// the scene): a magenta and black checkerboard, `count` images of side 8.
std::shared_ptr<const EnvironmentImages> placeholderEnvironmentImages(int count);

}  // namespace sdfwb::image
