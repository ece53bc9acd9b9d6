// The first-root reference for polynomial surfaces, and the live method
// (|F| / |grad F| with a step clamp) of both backends measured against it on
// the singular surfaces of scenes/hard/.

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "gl_test_support.h"
#include "parity/polynomial_reference.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb {
namespace {

TEST(PolynomialReference, FindsTheFirstRootOfKnownPolynomials) {
    // (t - 1)(t - 2)(t - 3)
    std::vector<double> cubic = {-6, 11, -6, 1};
    EXPECT_NEAR(*parity::firstRoot(cubic, 0, 10), 1.0, 1e-9);
    EXPECT_NEAR(*parity::firstRoot(cubic, 1.5, 10), 2.0, 1e-9);
    EXPECT_FALSE(parity::firstRoot(cubic, 3.5, 10).has_value());
    // a double root (tangent ray): (t - 2)^2
    EXPECT_NEAR(*parity::firstRoot({4, -4, 1}, 0, 5), 2.0, 1e-5);
    // no real root: t^2 + 1
    EXPECT_FALSE(parity::firstRoot({1, 0, 1}, -5, 5).has_value());
}

TEST(PolynomialReference, RestrictsThePolynomialToTheRay) {
    parity::PolynomialTerms sphere = parity::polynomialTerms("x^2 + y^2 + z^2 - 1");
    // from (0, 0, 3) along -z: t^2 - 6t + 8 = (t - 2)(t - 4)
    std::vector<double> c = parity::alongRay(sphere, {0, 0, 3}, {0, 0, -1});
    ASSERT_EQ(c.size(), 3u);
    EXPECT_DOUBLE_EQ(c[0], 8);
    EXPECT_DOUBLE_EQ(c[1], -6);
    EXPECT_DOUBLE_EQ(c[2], 1);
    EXPECT_NEAR(*parity::firstRoot(c, 0, 10), 2.0, 1e-9);
}

class SingularSurface : public test::GlTest, public ::testing::WithParamInterface<const char*> {};

// No holes anywhere; false hits away from the silhouette only along the 1-D
// parts of the variety (the Whitney umbrella's handle, the Roman surface's
// axes), which lie on F = 0 but which a ray meets with probability zero, so
// the first-root reference misses them: at most a one-pixel line.
TEST_P(SingularSurface, LiveMethodHasNoHolesAndAtMostLineFalseHits) {
    scene::Scene s = scene::loadSceneFile(std::string(SDFWB_SOURCE_DIR "/scenes/hard/") + GetParam() + ".json");
    const int w = 240, h = 135;
    auto reference = parity::referenceDepths(s, w, h);
    program::Program p = program::compileScene(s, {.width = w, .height = h, .aa = 1});
    gl::GlRenderer renderer(gl());
    for (const auto& [label, frame] : {std::pair{"CPU", cpu::renderCpu(p).frame}, std::pair{"GL", renderer.render(p).frame}}) {
        parity::PolynomialAccuracy a = parity::measureAccuracy(reference, frame);
        std::cout << parity::describeAccuracy(std::string(GetParam()) + " " + label, a) << "\n";
        EXPECT_GT(a.referenceHits, 500u);
        EXPECT_EQ(a.interiorHoles, 0u) << label;
        EXPECT_LE(a.holes, a.pixels / 1000) << label;
        EXPECT_LE(a.interiorFalseHits, a.pixels / 200) << label;
        EXPECT_LT(a.meanRelativeDepthError, 0.02) << label;
    }
}

INSTANTIATE_TEST_SUITE_P(Hard, SingularSurface, ::testing::Values("whitney_umbrella", "cone_apex", "roman_surface"));

}  // namespace
}  // namespace sdfwb
