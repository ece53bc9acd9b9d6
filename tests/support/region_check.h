#pragma once
// The region contract of render::RenderControl: a render of a region holds
// the whole frame's pixels inside it and blank pixels outside.

#include <gtest/gtest.h>

#include "image/image.h"
#include "render/tiles.h"

namespace sdfwb::test {

inline void expectRegionOfFrame(const image::Frame& whole, const image::Frame& part, const render::TileRect& region) {
    ASSERT_EQ(part.color.width, whole.color.width);
    ASSERT_EQ(part.color.height, whole.color.height);
    int inside = 0, mismatches = 0, litOutside = 0;
    for (int y = 0; y < whole.color.height; ++y) {
        for (int x = 0; x < whole.color.width; ++x) {
            const size_t i = static_cast<size_t>(y) * static_cast<size_t>(whole.color.width) + static_cast<size_t>(x);
            const bool in = x >= region.x && x < region.x + region.w && y >= region.y && y < region.y + region.h;
            for (int c = 0; c < 3; ++c) {
                const float expected = in ? whole.color.rgb[3 * i + c] : 0.0f;
                if (part.color.rgb[3 * i + c] != expected) (in ? mismatches : litOutside) += 1;
            }
            if (in && (part.steps[i] != whole.steps[i] || part.depth[i] != whole.depth[i])) ++mismatches;
            inside += in;
        }
    }
    EXPECT_EQ(inside, region.w * region.h);
    EXPECT_EQ(mismatches, 0) << "pixels inside the region differ from the whole frame's";
    EXPECT_EQ(litOutside, 0) << "pixels outside the region were rendered";
}

}  // namespace sdfwb::test
