#include "image/mipmaps.h"

#include <cstddef>

namespace sdfwb::image {

std::vector<glm::vec4> buildMipmaps(const std::vector<glm::vec4>& level0, int side) {
    std::vector<glm::vec4> texels = level0;
    std::size_t start = 0;  // of the level being halved
    for (int size = side; size > 1; size /= 2) {
        const int half = size / 2;
        auto at = [&](int column, int row) {
            return texels[start + static_cast<std::size_t>(row) * static_cast<std::size_t>(size) +
                          static_cast<std::size_t>(column)];
        };
        std::vector<glm::vec4> next;
        next.reserve(static_cast<std::size_t>(half) * static_cast<std::size_t>(half));
        for (int row = 0; row < half; ++row) {
            for (int column = 0; column < half; ++column) {
                next.push_back((at(2 * column, 2 * row) + at(2 * column + 1, 2 * row) + at(2 * column, 2 * row + 1) +
                                at(2 * column + 1, 2 * row + 1)) *
                               0.25f);
            }
        }
        start = texels.size();
        texels.insert(texels.end(), next.begin(), next.end());
    }
    return texels;
}

}  // namespace sdfwb::image
