// Solid procedural textures (texture.glsl) in the double build: the filtered
// checker and stripes against brute-force averages over the footprint's cube,
// noise within [0, 1] and fading to its mean, no texture leaving the material.

#include <cmath>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

// The point pattern's coverage averaged over n^3 points of the cube of side w about x.
double bruteForceCoverage(int pattern, vec3 x, double w, int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n; ++k) {
                vec3 y = x + w * (vec3(i + 0.5, j + 0.5, k + 0.5) / double(n) - vec3(0.5));
                sum += textureCoverage(pattern, y, 0.0);
            }
        }
    }
    return sum / (n * n * n);
}

TEST(SolidTexture, CheckerAndStripesAreTheAverageOverTheFootprint) {
    const vec3 points[] = {vec3(0.13, 0.71, -0.4), vec3(3.97, -2.2, 1.5), vec3(-0.49, 10.02, 0.25)};
    for (int pattern : {TEXTURE_CHECKER, TEXTURE_STRIPES}) {
        for (vec3 x : points) {
            for (double w : {0.05, 0.4, 1.3, 3.0}) {
                EXPECT_NEAR(textureCoverage(pattern, x, w), bruteForceCoverage(pattern, x, w, 160), 1.5e-2)
                    << pattern << " width " << w;
            }
        }
    }
}

TEST(SolidTexture, NoiseStaysInRangeAndFadesToItsMean) {
    for (int i = 0; i < 2000; ++i) {
        vec3 x(std::sin(i * 1.7) * 40, std::cos(i * 0.3) * 40, i * 0.013);
        double sharp = textureCoverage(TEXTURE_NOISE, x, 0.0);
        EXPECT_GE(sharp, 0.0);
        EXPECT_LE(sharp, 1.0);
        EXPECT_NEAR(textureCoverage(TEXTURE_NOISE, x, 1.0), 0.5, 1e-12);
    }
}

TEST(SolidTexture, NoneLeavesTheMaterial) {
    Material base = noMaterial();
    base.diffuse = vec3(0.3, 0.6, 0.9);
    Material m = texturedMaterial(base, TEXTURE_NONE, vec3(0.7, 0.1, 0.2), 0.0, vec3(1, 0, 0), true);
    EXPECT_EQ(m.diffuse, base.diffuse);
    EXPECT_EQ(m.ambient, base.ambient);
}

TEST(SolidTexture, ThePatternMixesTheSpecularColourOnlyWhenAsked) {
    Material base = noMaterial();
    base.specular = vec3(0.2, 0.4, 0.6);
    const vec3 colour(1, 0, 0);
    // a checker cell's inside, far from its edges: full coverage
    vec3 inside(1.5, 0.5, 0.5);
    ASSERT_EQ(textureCoverage(TEXTURE_CHECKER, inside, 0.0), 1.0);
    EXPECT_EQ(texturedMaterial(base, TEXTURE_CHECKER, inside, 0.0, colour, false).specular, base.specular);
    EXPECT_EQ(texturedMaterial(base, TEXTURE_CHECKER, inside, 0.0, colour, true).specular, colour);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
