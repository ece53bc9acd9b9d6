#pragma once
// Mipmaps as the lecture notes on realism (1.1) define them: from a 2^n x 2^n
// image, n further levels, each texel the mean of the four texels of the level
// before, M_(i+1)[j, k] = (M_i[2j, 2k] + M_i[2j+1, 2k] + M_i[2j, 2k+1] + M_i[2j+1, 2k+1]) / 4,
// down to 1 x 1. Stored as the shared sampler reads them (sdf/glsl/environment.glsl):
// level after level, each row-major.

#include <vector>

#include <glm/vec4.hpp>

namespace sdfwb::image {

// `level0` holds side x side texels (side a power of two); the result starts
// with them and holds (4 side^2 - 1) / 3 texels.
std::vector<glm::vec4> buildMipmaps(const std::vector<glm::vec4>& level0, int side);

}  // namespace sdfwb::image
