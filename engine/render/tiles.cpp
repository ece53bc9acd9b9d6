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

std::vector<TileRect> tilesToRender(int width, int height, const std::optional<TileRect>& region, int tile) {
    if (!region) return tileGrid(width, height, tile);
    const int x0 = std::clamp(region->x, 0, width), y0 = std::clamp(region->y, 0, height);
    const int x1 = std::clamp(region->x + std::max(region->w, 0), x0, width);
    const int y1 = std::clamp(region->y + std::max(region->h, 0), y0, height);
    std::vector<TileRect> tiles = tileGrid(x1 - x0, y1 - y0, tile);
    for (TileRect& t : tiles) {
        t.x += x0;
        t.y += y0;
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
