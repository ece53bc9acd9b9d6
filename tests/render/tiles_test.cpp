// The one tile layout: every pixel in exactly one tile, row by row from the top.

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

#include "render/tiles.h"

namespace sdfwb {
namespace {

TEST(TileGrid, CoversEveryPixelOnceWithCroppedEdges) {
    for (auto [w, h, tile] : {std::tuple{100, 37, 16}, {1, 1, 32}, {64, 64, 32}, {33, 65, 7}}) {
        std::vector<int> hits(static_cast<size_t>(w) * h, 0);
        for (const render::TileRect& t : render::tileGrid(w, h, tile)) {
            EXPECT_LE(t.w, tile);
            EXPECT_LE(t.h, tile);
            for (int y = t.y; y < t.y + t.h; ++y) {
                for (int x = t.x; x < t.x + t.w; ++x) ++hits[static_cast<size_t>(y) * w + x];
            }
        }
        EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), w * h) << w << "x" << h << " in " << tile;
    }
}

TEST(TileGrid, RowsFromTheTopLeft) {
    std::vector<render::TileRect> tiles = render::tileGrid(40, 20, 16);
    std::vector<render::TileRect> expected = {{0, 0, 16, 16}, {16, 0, 16, 16}, {32, 0, 8, 16},
                                              {0, 16, 16, 4}, {16, 16, 16, 4}, {32, 16, 8, 4}};
    EXPECT_EQ(tiles, expected);
    EXPECT_TRUE(render::tileGrid(0, 10, 16).empty());
}

TEST(TilesToRender, ARegionIsClippedToTheFrameAndTiledFromItsCorner) {
    EXPECT_EQ(render::tilesToRender(40, 20, std::nullopt, 16), render::tileGrid(40, 20, 16));
    std::vector<render::TileRect> expected = {{5, 3, 16, 16}, {21, 3, 4, 16}, {5, 19, 16, 1}, {21, 19, 4, 1}};
    EXPECT_EQ(render::tilesToRender(40, 20, render::TileRect{5, 3, 20, 100}, 16), expected);
    EXPECT_TRUE(render::tilesToRender(40, 20, render::TileRect{50, 0, 10, 10}, 16).empty());
    EXPECT_TRUE(render::tilesToRender(40, 20, render::TileRect{-30, 0, 10, 10}, 16).empty());
    EXPECT_TRUE(render::tilesToRender(40, 20, render::TileRect{3, 3, -5, 10}, 16).empty());
}

TEST(BlankFrame, HasEveryChannelAtZero) {
    image::Frame frame = render::blankFrame(3, 2);
    EXPECT_EQ(frame.color.rgb, std::vector<float>(18, 0.0f));
    EXPECT_EQ(frame.steps, std::vector<float>(6, 0.0f));
    EXPECT_EQ(frame.coverage, std::vector<float>(6, 0.0f));
    EXPECT_EQ(frame.depth, std::vector<float>(6, 0.0f));
}

}  // namespace
}  // namespace sdfwb
