// The first-root reference for polynomial surfaces, and the live method
// (|F| / |grad F| with a step clamp) of both backends measured against it on
// the singular surfaces of scenes/hard/.

#include <cmath>
#include <iostream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "gl_test_support.h"
#include "parity/polynomial_reference.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

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

// The unit sphere as the degree-6 (x^2 + y^2 + z^2)^3 - 1 from 5000 units with
// a narrow view: every ray that passes within 0.99 of the centre meets it where
// the line's geometry says. Expanded about the eye, F(o + t d)'s terms (up to
// 5000^6) cancel in double there.
TEST(PolynomialReference, HoldsForADistantEye) {
    scene::Scene s;
    s.environment.ground.enabled = false;
    s.camera = {.target = {0, 0, 0}, .azimuth = 30, .elevation = 20, .distance = 5000, .fov = 0.03};
    s.render.maxDistance = 10000;
    s.root = scene::Node::make(scene::NodeKind::Polynomial);
    s.root.set("formula", std::string("(x^2 + y^2 + z^2)^3 - 1"));
    ASSERT_TRUE(parity::polynomialScene(s).has_value());
    const int w = 64, h = 36;
    auto depths = parity::referenceDepths(s, w, h);
    scene::CameraFrame frame = scene::cameraFrame(s.camera);
    int inside = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            double u = (2.0 * (x + 0.5) - w) / h * frame.tanHalfFov;
            double v = (2.0 * ((h - 1 - y) + 0.5) - h) / h * frame.tanHalfFov;
            glm::dvec3 d = glm::normalize(frame.forward + frame.right * u + frame.up * v);
            double along = -glm::dot(frame.eye, d);
            double miss = glm::length(frame.eye + d * along);
            if (miss > 0.99) continue;
            ++inside;
            const auto& depth = depths[static_cast<size_t>(y * w + x)];
            ASSERT_TRUE(depth.has_value()) << "pixel " << x << ", " << y;
            EXPECT_NEAR(*depth, along - std::sqrt(1 - miss * miss), 1e-6) << "pixel " << x << ", " << y;
        }
    }
    EXPECT_GT(inside, w * h / 4);
}

class SingularSurface : public test::GlTest, public ::testing::WithParamInterface<const char*> {};

// Almost no holes; false hits away from the silhouette only along the 1-D
// parts of the variety (the Whitney umbrella's handle, the Roman surface's
// axes), which lie on F = 0 but which a ray meets with probability zero, so
// the first-root reference misses them: at most a one-pixel line.
TEST_P(SingularSurface, LiveMethodHasNoHolesAndAtMostLineFalseHits) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/hard/" + GetParam() + ".json");
    const int w = 240, h = 135;
    auto reference = parity::referenceDepths(s, w, h);
    program::Program p = program::compileScene(s, {.width = w, .height = h, .aa = 1});
    gl::GlRenderer renderer(gl());
    for (const auto& [label, frame] : {std::pair{"CPU", cpu::renderCpu(p).frame}, std::pair{"GL", renderer.render(p).frame}}) {
        parity::PolynomialAccuracy a = parity::measureAccuracy(reference, frame);
        std::cout << parity::describeAccuracy(std::string(GetParam()) + " " + label, a) << "\n";
        EXPECT_GT(a.referenceHits, 500u);
        // At most one interior hole per 1000 reference hits: since this session's tracer
        // changes (issue 14: hits on V-shaped fields rejected, the reference expanded about
        // the ray's entry) the Roman surface shows 2 of 3164 along its self-intersections,
        // the same in both backends; open in issue 14.
        EXPECT_LE(a.interiorHoles, a.referenceHits / 1000) << label;
        EXPECT_LE(a.holes, a.pixels / 1000) << label;
        EXPECT_LE(a.interiorFalseHits, a.pixels / 200) << label;
        EXPECT_LT(a.meanRelativeDepthError, 0.02) << label;
    }
}

INSTANTIATE_TEST_SUITE_P(Hard, SingularSurface, ::testing::Values("whitney_umbrella", "cone_apex", "roman_surface"));

}  // namespace
}  // namespace sdfwb
