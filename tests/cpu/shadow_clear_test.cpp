// A shadow ray ends without further samples once they can no longer change
// its outcome (tracer.glsl's shadowRayClear): every surface but the ground
// lies in the scene's bounding sphere, so a ray whose remaining points stay
// clear of that sphere and of the ground by its penumbra's reach cannot be
// darkened. The test is conservative (never ends a ray that could still come
// within reach), renders what sampling the whole ray renders, and spares
// most shadow samples of a ball on an open floor.

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/scene.h"
#include "support/ball_on_the_floor.h"
#include "support/traced_program.h"

namespace sdfwb {
namespace {

using glm::dvec3;
namespace f64 = cpu::f64;

constexpr int kWidth = 64, kHeight = 36;

// A shadow ray at its next sample: origin o (the normal left at 0, so o is
// the shadow origin itself), shadowT along `direction`.
f64::TraceState shadowRayAt(dvec3 origin, double shadowT, double result, double epsilon) {
    f64::TraceState s = f64::traceBegin(f64::Ray(origin, dvec3(0, 0, 1)));
    s.phase = f64::PHASE_SHADOW;
    s.hitPoint = origin;
    s.normal = dvec3(0.0);
    s.hitEpsilon = epsilon;
    s.shadowT = shadowT;
    s.shadowResult = result;
    return s;
}

TEST(ShadowClear, EndsOnlyRaysThatStayOutOfReachOfEverySurface) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int cleared = 0, tried = 0;
    for (int i = 0; i < 4000; ++i) {
        f64::TraceSettings settings{};
        settings.shadowMode = i % 3 == 0 ? f64::SHADOW_HARD : i % 3 == 1 ? f64::SHADOW_SOFT : f64::SHADOW_IMPROVED;
        settings.maxDistance = 40.0;
        settings.boundsUse = f64::BOUNDS_END_SHADOW_RAYS;
        settings.boundsCenter = dvec3(unit(random), unit(random), unit(random)) * 3.0;
        settings.boundsRadius = 0.2 + 2.0 * fraction(random);
        settings.groundPlane = i % 2;
        settings.groundHeight = settings.boundsCenter.y - settings.boundsRadius - 0.5 * fraction(random);
        f64::Light light{};
        light.direction = glm::normalize(dvec3(unit(random), unit(random), unit(random)));
        light.softness = 1.5 + 14.0 * fraction(random);
        dvec3 origin = settings.boundsCenter + dvec3(unit(random), unit(random), unit(random)) * 8.0;
        double shadowT = fraction(random) < 0.3 ? 0.0 : 5.0 * fraction(random);
        double result = fraction(random) < 0.3 ? 1.0 : 1.2 * fraction(random) - 0.2;
        double epsilon = 1e-3 * (1.0 + 10.0 * fraction(random));
        f64::TraceState s = shadowRayAt(origin - light.direction * shadowT, shadowT, result, epsilon);
        ++tried;
        if (!f64::shadowRayClear(s, light, settings)) continue;
        ++cleared;
        // the distance below which a sample at T + u could change the outcome
        double slope = settings.shadowMode == f64::SHADOW_HARD ? 0.0 : std::max(result, 0.0) / light.softness;
        for (int k = 0; k <= 4000; ++k) {
            double u = (settings.maxDistance - shadowT) * k / 4000.0;
            dvec3 p = origin + light.direction * u;
            double reach = slope * (shadowT + u) + epsilon;
            ASSERT_GE(glm::length(p - settings.boundsCenter) - settings.boundsRadius, reach * (1 - 1e-12))
                << "ray " << i << " at u = " << u;
            if (settings.groundPlane != 0) {
                ASSERT_GE(p.y - settings.groundHeight, reach * (1 - 1e-12)) << "ray " << i << " at u = " << u;
            }
        }
    }
    // and it is no test that says no to everything
    EXPECT_GT(cleared, tried / 5);
}

TEST(ShadowClear, ARayHeadingAwayIsClearAndOneTowardsTheSphereIsNot) {
    f64::TraceSettings settings{};
    settings.shadowMode = f64::SHADOW_SOFT;
    settings.maxDistance = 40.0;
    settings.boundsUse = f64::BOUNDS_END_SHADOW_RAYS;
    settings.boundsCenter = dvec3(0.0);
    settings.boundsRadius = 1.0;
    f64::Light light{};
    light.direction = dvec3(0, 1, 0);
    light.softness = 8.0;
    EXPECT_TRUE(f64::shadowRayClear(shadowRayAt(dvec3(0, 2, 0), 0.0, 1.0, 1e-3), light, settings));
    EXPECT_FALSE(f64::shadowRayClear(shadowRayAt(dvec3(0, -2, 0), 0.0, 1.0, 1e-3), light, settings));
    // passing beside the sphere within its penumbra's reach (k d / t < 1)
    EXPECT_FALSE(f64::shadowRayClear(shadowRayAt(dvec3(1.1, -2, 0), 0.0, 1.0, 1e-3), light, settings));
    // a scene without bounds (an unbounded primitive) ends no ray early
    settings.boundsUse = 0;
    EXPECT_FALSE(f64::shadowRayClear(shadowRayAt(dvec3(0, 2, 0), 0.0, 1.0, 1e-3), light, settings));
    // nor does a light below the ground's horizon
    settings.boundsUse = f64::BOUNDS_END_SHADOW_RAYS;
    settings.groundPlane = 1;
    settings.groundHeight = -1.0;
    light.direction = glm::normalize(dvec3(1, -0.01, 0));
    EXPECT_FALSE(f64::shadowRayClear(shadowRayAt(dvec3(0, 2, 0), 0.0, 1.0, 1e-3), light, settings));
}

// The ball on the floor under a light at a slant.
scene::Scene ballOnTheFloor(scene::ShadowMode shadows) {
    scene::Scene s = test::ballOnTheFloor();
    s.lights = {scene::Light{}};
    s.lights[0].direction = dvec3(0.6, 1.0, 0.3);
    s.lights[0].softness = 8.0;
    s.camera.elevation = 25.0;
    s.camera.distance = 7.0;
    s.render.shadows = shadows;
    return s;
}

TEST(ShadowClear, RendersWhatTheWholeRayRendersWithFewerSamples) {
    for (scene::ShadowMode mode : {scene::ShadowMode::Hard, scene::ShadowMode::Soft, scene::ShadowMode::Improved}) {
        program::Program program = program::compileScene(ballOnTheFloor(mode), {kWidth, kHeight, 1});
        int boundsUse = test::traceSettingsOf(program).boundsUse;
        ASSERT_NE(boundsUse & f64::BOUNDS_END_SHADOW_RAYS, 0) << "a ball has bounds";
        // the same primary rays, shadow rays sampled to their ends
        test::TracedProgram cleared(program),
            whole(test::withBoundsUse(program, boundsUse & ~f64::BOUNDS_END_SHADOW_RAYS));
        long clearedEvaluations = 0, wholeEvaluations = 0;
        double worst = 0.0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                f64::SampleResult a = cleared.at(x, y), b = whole.at(x, y);
                ASSERT_EQ(a.hit, b.hit);
                clearedEvaluations += a.evaluations;
                wholeEvaluations += b.evaluations;
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.color[c] - b.color[c]));
            }
        }
        int m = static_cast<int>(mode);
        // the outcome of every ray is that of the whole ray: the samples
        // skipped lie beyond the penumbra's reach, where k d / t >= result
        EXPECT_LT(worst, 1e-6) << "mode " << m;
        EXPECT_LT(2 * clearedEvaluations, wholeEvaluations)
            << "mode " << m << ": " << clearedEvaluations << " against " << wholeEvaluations;
    }
}

}  // namespace
}  // namespace sdfwb
