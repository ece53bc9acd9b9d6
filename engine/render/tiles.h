#pragma once
// The tile layout every render walks (CPU tiles across threads, GL draws
// within a time budget), and the frame tiles are written into.

#include <optional>
#include <vector>

#include "image/image.h"

namespace sdfwb::render {

// A rectangle of the frame, rows counted from the top.
struct TileRect {
    int x = 0, y = 0, w = 0, h = 0;
    friend bool operator==(const TileRect&, const TileRect&) = default;
};

// Row by row from the top left, `tile` pixels per side (edge tiles are
// cropped to the frame); empty for an empty frame. Requires tile >= 1.
std::vector<TileRect> tileGrid(int width, int height, int tile);

// The tiles a render of a width x height frame walks: the whole grid, or with
// a region only the tiles of that rectangle (clipped to the frame; its own
// grid from its top left corner). Requires tile >= 1.
std::vector<TileRect> tilesToRender(int width, int height, const std::optional<TileRect>& region, int tile);

// A frame of the given size with zeroed colour and statistics.
image::Frame blankFrame(int width, int height);

}  // namespace sdfwb::render
