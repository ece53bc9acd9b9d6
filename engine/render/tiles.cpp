#include "render/tiles.h"

#include <algorithm>

namespace sdfwb::render {

std::vector<TileRect> tileGrid(int width, int height, int tile) {
    std::vector<TileRect> tiles;
    for (int y = 0; y < height; y += tile) {
        for (int x = 0; x < width; x += tile) {
            tiles.push_back({x, y, std::min(tile, width - x), std::min(tile, height - y)});
        }
    }
    return tiles;
}

image::Frame blankFrame(int width, int height) {
    image::Frame frame;
    frame.color = image::Image(width, height);
    frame.steps.assign(frame.color.pixelCount(), 0.0f);
    frame.evaluations.assign(frame.color.pixelCount(), 0.0f);
    frame.coverage.assign(frame.color.pixelCount(), 0.0f);
    frame.depth.assign(frame.color.pixelCount(), 0.0f);
    return frame;
}

}  // namespace sdfwb::render
