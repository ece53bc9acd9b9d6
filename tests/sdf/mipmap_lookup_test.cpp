// The notes' mipmap access (sdf/glsl/mipmap_lookup.glsl) in the double build,
// against its definition: the level is log2 of the footprint in level-0
// texels, so it grows by 1 each time the distance doubles (the notes: linear
// in the logarithm of the distance); an integer level reads that level
// alone, and a fractional one mixes the two nearest linearly.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

// A 4 x 4 image with its levels as the texel buffer holds them
// (environment.glsl's mipLevelOffset): level 0 a checker of 1 and 0, each
// level below the mean of four texels of the one before, 0.5 everywhere.
struct CheckerPyramid {
    std::vector<vec4> texels;

    CheckerPyramid() {
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) texels.push_back(vec4((i + j) % 2 == 0 ? 1.0 : 0.0));
        for (int i = 0; i < 4 + 1; ++i) texels.push_back(vec4(0.5));
    }
    vec4 T(int i) const { return texels.at(static_cast<size_t>(i)); }

#include "sdf/glsl/mipmap_lookup.glsl"
};

constexpr int kSide = 4;
constexpr int kLevels = 3;

TEST(MipmapLookup, TheLevelIsTheLog2OfTheFootprintInTexels) {
    CheckerPyramid image;
    for (int k = 0; k <= 10; ++k) EXPECT_NEAR(image.mipLevelOfFootprint(std::ldexp(1.0, k)), k, 1e-12) << k;
    for (double texels : {1.5, 3.0, 7.25, 100.0}) {
        EXPECT_NEAR(image.mipLevelOfFootprint(texels), std::log2(texels), 1e-12) << texels;
        // twice the distance, twice the footprint: one level coarser
        EXPECT_NEAR(image.mipLevelOfFootprint(2 * texels) - image.mipLevelOfFootprint(texels), 1, 1e-12) << texels;
    }
    // a footprint within one texel reads the full image
    EXPECT_EQ(image.mipLevelOfFootprint(1.0), 0.0);
    EXPECT_EQ(image.mipLevelOfFootprint(0.25), 0.0);
    EXPECT_EQ(image.mipLevelOfFootprint(0.0), 0.0);
}

TEST(MipmapLookup, AnIntegerLevelReadsThatLevelAndAFractionMixesTheTwoNearest) {
    CheckerPyramid image;
    // the centre of texel (1, 2) of level 0, whose value is 0 ((1 + 2) odd)
    double u = 1.5 / kSide, v = 2.5 / kSide;
    auto at = [&](double lod) { return image.sampleMipmap(0, kSide, kLevels, u, v, lod, true, true).x; };
    EXPECT_EQ(at(0), 0.0);
    EXPECT_EQ(at(1), 0.5);
    EXPECT_EQ(at(2), 0.5);
    EXPECT_DOUBLE_EQ(at(0.25), 0.75 * 0.0 + 0.25 * 0.5);
    EXPECT_DOUBLE_EQ(at(0.5), 0.25);
    // beyond the pyramid it stays on its ends
    EXPECT_EQ(at(-3), at(0));
    EXPECT_EQ(at(7), at(2));
    // the centre of texel (2, 2), value 1
    EXPECT_EQ(image.sampleMipmap(0, kSide, kLevels, 2.5 / kSide, v, 0, true, true).x, 1.0);
    EXPECT_DOUBLE_EQ(image.sampleMipmap(0, kSide, kLevels, 2.5 / kSide, v, 0.75, true, true).x, 0.25 + 0.75 * 0.5);
}

// Between texel centres a level is read bilinearly: half way between a 1
// and a 0 texel is their mean, which is what the level below holds.
TEST(MipmapLookup, ALevelIsReadBilinearlyBetweenTexelCentres) {
    CheckerPyramid image;
    double v = 2.5 / kSide;
    EXPECT_DOUBLE_EQ(image.sampleMipmap(0, kSide, kLevels, 2.0 / kSide, v, 0, true, true).x, 0.5);
    EXPECT_DOUBLE_EQ(image.sampleMipmap(0, kSide, kLevels, 1.75 / kSide, v, 0, true, true).x, 0.25);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
