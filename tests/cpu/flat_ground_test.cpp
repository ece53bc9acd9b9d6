// A floor far from the scene's objects is shaded as the plane it is
// (tracer.glsl's skipFlatGround, tracing "bounded"): where nothing but the
// ground lies within the normal's or the occlusion's reach of a hit, the
// tracer takes the plane's normal and its want of occlusion instead of
// sampling them. The image is the one the samples give; only the count of
// evaluations changes. A ground with a bump map keeps its samples.

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
constexpr int kAllBoundsUses = f64::BOUNDS_END_SHADOW_RAYS | f64::BOUNDS_SKIP_MARCH | f64::BOUNDS_FLAT_GROUND;

f64::TraceState hitAt(dvec3 point, double epsilon) {
    f64::TraceState s = f64::traceBegin(f64::Ray(point, dvec3(0, -1, 0)));
    s.hitPoint = point;
    s.hitEpsilon = epsilon;
    return s;
}

// Every point within reach of a hit it answers for lies more than reach plus
// epsilon from the bounding sphere, so only the ground, at most that high
// above those points, can be nearest to them.
TEST(FlatGround, AnswersOnlyWhereEveryPointWithinReachIsFartherFromTheBoundsThanFromTheGround) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int answered = 0;
    for (int i = 0; i < 4000; ++i) {
        f64::TraceSettings settings{};
        settings.boundsUse = f64::BOUNDS_FLAT_GROUND;
        settings.boundsCenter = dvec3(unit(random), 1.0 + unit(random), unit(random)) * 3.0;
        settings.boundsRadius = 0.2 + 2.0 * fraction(random);
        double epsilon = 1e-3 * (1.0 + 10.0 * fraction(random));
        double reach = fraction(random) < 0.5 ? f64::NORMAL_REACH * epsilon : 2.0 * fraction(random);
        dvec3 hit(8.0 * unit(random), 0.0, 8.0 * unit(random));
        f64::TraceState s = hitAt(hit, epsilon);
        if (!f64::onlyGroundWithin(s, settings, reach)) continue;
        ++answered;
        for (int k = 0; k < 64; ++k) {
            dvec3 offset = glm::normalize(dvec3(unit(random), unit(random), unit(random))) * (reach * fraction(random));
            double toBounds = glm::length(hit + offset - settings.boundsCenter) - settings.boundsRadius;
            ASSERT_GT(toBounds, reach + epsilon) << "case " << i;
        }
    }
    EXPECT_GT(answered, 1000);
    f64::TraceSettings off{};
    off.boundsCenter = dvec3(0, 100, 0);
    EXPECT_FALSE(f64::onlyGroundWithin(hitAt(dvec3(0), 1e-3), off, 1.0)) << "the bit is off";
}

// The ball on the floor from above at a slant, one soft light, occlusion on.
scene::Scene ballScene() {
    scene::Scene s = test::ballOnTheFloor();
    s.camera.elevation = 25.0;
    s.camera.distance = 9.0;
    s.render.aoSamples = 4;
    s.render.aoDistance = 0.5;
    return s;
}

TEST(FlatGround, ShadesTheOpenFloorAsItsSamplesWouldWithFewerEvaluations) {
    program::Program program = program::compileScene(ballScene(), {kWidth, kHeight, 1});
    ASSERT_EQ(test::traceSettingsOf(program).boundsUse, kAllBoundsUses);
    test::TracedProgram planar(program),
        sampled(test::withBoundsUse(program, f64::BOUNDS_END_SHADOW_RAYS | f64::BOUNDS_SKIP_MARCH));
    long planarEvaluations = 0, sampledEvaluations = 0, spared = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            f64::SampleResult a = planar.at(x, y), b = sampled.at(x, y);
            ASSERT_EQ(a.hit, b.hit) << x << ", " << y;
            EXPECT_EQ(a.t, b.t) << x << ", " << y;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.color[c], b.color[c], 1e-9) << x << ", " << y;
            planarEvaluations += a.evaluations;
            sampledEvaluations += b.evaluations;
            // the normal's four samples and the occlusion's four
            spared += b.evaluations - a.evaluations == 8 ? 1 : 0;
        }
    }
    EXPECT_GT(spared, kWidth * kHeight / 4) << "the open floor";
    EXPECT_LT(planarEvaluations, sampledEvaluations);
}

TEST(FlatGround, AGroundWithABumpMapKeepsItsSamples) {
    scene::Scene s = ballScene();
    scene::Material bumped;
    bumped.name = "bumped";
    bumped.bump = scene::BumpPattern::Waves;
    s.materials.push_back(bumped);
    s.environment.ground.material = "bumped";
    EXPECT_EQ(test::traceSettingsOf(program::compileScene(s, {kWidth, kHeight, 1})).boundsUse,
              f64::BOUNDS_END_SHADOW_RAYS | f64::BOUNDS_SKIP_MARCH);
    s.render.tracing = scene::Tracing::Plain;
    EXPECT_EQ(test::traceSettingsOf(program::compileScene(s, {kWidth, kHeight, 1})).boundsUse, 0);
}

}  // namespace
}  // namespace sdfwb
