// The march crosses empty space without samples (tracer.glsl's
// emptyMarchAhead, tracing "bounded"): every surface but the ground lies in
// the scene's bounding sphere, so from a point outside it the ray meets
// nothing before it enters that sphere or lands on the ground plane. The skip
// never passes a point within epsilon of the sphere or below the ground,
// finds the surfaces the stepping march finds, and spares the rays that miss
// the scene every sample.

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

f64::TraceState marchAt(dvec3 origin, dvec3 direction, double t) {
    f64::TraceState s = f64::traceBegin(f64::Ray(origin, direction));
    s.t = t;
    return s;
}

TEST(EmptyMarch, SkipsOnlySpaceFartherThanEpsilonFromTheBoundsAndAboveTheGround) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int skipped = 0, tried = 0, ended = 0;
    for (int i = 0; i < 4000; ++i) {
        f64::TraceSettings settings{};
        settings.maxDistance = 40.0;
        settings.epsilon = 1e-3 * (1.0 + 10.0 * fraction(random));
        settings.epsilonPerDistance = i % 3 == 0 ? 1e-3 * fraction(random) : 0.0;
        settings.boundsUse = f64::BOUNDS_SKIP_MARCH;
        settings.boundsCenter = dvec3(unit(random), unit(random), unit(random)) * 3.0;
        settings.boundsRadius = 0.2 + 2.0 * fraction(random);
        settings.groundPlane = i % 2;
        settings.groundHeight = settings.boundsCenter.y - settings.boundsRadius - 0.5 * fraction(random);
        dvec3 direction = glm::normalize(dvec3(unit(random), unit(random), unit(random)));
        double t = fraction(random) < 0.5 ? 0.0 : 10.0 * fraction(random);
        dvec3 origin = settings.boundsCenter + dvec3(unit(random), unit(random), unit(random)) * 8.0 - direction * t;
        f64::TraceState s = marchAt(origin, direction, t);
        ++tried;
        double ahead = f64::emptyMarchAhead(s, settings);
        if (!(ahead > 0.0)) continue;
        ++skipped;
        double epsilon = f64::hitEpsilonAt(settings, settings.maxDistance);
        double span = std::min(ahead, settings.maxDistance - t);
        ended += ahead >= f64::GROUND_CLEAR_STEP ? 1 : 0;
        for (int k = 0; k <= 4000; ++k) {
            double u = span * k / 4000.0;
            dvec3 p = origin + direction * (t + u);
            ASSERT_GE(glm::length(p - settings.boundsCenter) - settings.boundsRadius, epsilon * (1 - 1e-9))
                << "ray " << i << " at u = " << u;
            if (settings.groundPlane != 0) {
                // from a point clear of the ground onto it, never below it
                ASSERT_GE(p.y - settings.groundHeight, k == 0 ? epsilon : -1e-9) << "ray " << i << " at u = " << u;
            }
        }
    }
    // and it is no test that says no to everything
    EXPECT_GT(skipped, tried / 4);
    EXPECT_GT(ended, 0);
}

TEST(EmptyMarch, StopsAtTheWidenedSphereAndNeverFromInsideIt) {
    f64::TraceSettings settings{};
    settings.maxDistance = 40.0;
    settings.epsilon = 1e-2;
    settings.boundsUse = f64::BOUNDS_SKIP_MARCH;
    settings.boundsCenter = dvec3(0.0);
    settings.boundsRadius = 1.0;
    // straight at the sphere from 5 away: to its entry, one margin (epsilon) early,
    // before the sphere widened by epsilon
    EXPECT_NEAR(f64::emptyMarchAhead(marchAt(dvec3(0, 0, -5), dvec3(0, 0, 1), 0.0), settings), 3.98, 1e-12);
    // inside the sphere, or with the skip not asked for: none
    EXPECT_EQ(f64::emptyMarchAhead(marchAt(dvec3(0, 0, -0.5), dvec3(0, 0, 1), 0.0), settings), 0.0);
    settings.boundsUse = f64::BOUNDS_END_SHADOW_RAYS;
    EXPECT_EQ(f64::emptyMarchAhead(marchAt(dvec3(0, 0, -5), dvec3(0, 0, 1), 0.0), settings), 0.0);
    // past it, heading away: nothing ahead
    settings.boundsUse = f64::BOUNDS_SKIP_MARCH;
    EXPECT_EQ(f64::emptyMarchAhead(marchAt(dvec3(0, 0, 5), dvec3(0, 0, 1), 0.0), settings), f64::GROUND_CLEAR_STEP);
    // a ground below: onto it, h / -dir.y
    settings.groundPlane = 1;
    settings.groundHeight = -2.0;
    dvec3 down = glm::normalize(dvec3(0, -1, 1));
    EXPECT_NEAR(f64::emptyMarchAhead(marchAt(dvec3(0, 0, 5), down, 0.0), settings), 2.0 * std::sqrt(2.0), 1e-12);
}

// A ray that enters the bounds after max distance, above a floor it would
// meet just past max distance: the skip stops at max distance, where one
// sample decides whether the floor is within epsilon (advanceMarch), and
// a ray that meets neither ends on the background without a sample.
TEST(EmptyMarch, AGroundPastMaxDistanceGetsItsSampleThere) {
    f64::TraceSettings settings{};
    settings.maxDistance = 10.0;
    settings.epsilon = 1e-2;
    settings.boundsUse = f64::BOUNDS_SKIP_MARCH;
    settings.boundsCenter = dvec3(0, -0.6, 10.95);  // entered 10.06 away (one margin early)
    settings.boundsRadius = 1.0;
    settings.groundPlane = 1;
    settings.groundHeight = -1.005;
    dvec3 down = glm::normalize(dvec3(0, -0.1, 1));  // meets the floor 10.1 away
    ASSERT_NEAR(f64::emptyMarchAhead(marchAt(dvec3(0, 0, 0), down, 0.0), settings), 10.0636, 1e-3);
    f64::TraceState s = f64::skipEmptyMarch(marchAt(dvec3(0, 0, 0), down, 0.0), settings);
    EXPECT_EQ(s.phase, f64::PHASE_MARCH);
    EXPECT_EQ(s.t, settings.maxDistance);
    EXPECT_EQ(s.steps, 0) << "a skip takes no step of the budget";
    settings.groundPlane = 0;
    s = f64::skipEmptyMarch(marchAt(dvec3(0, 0, 0), down, 0.0), settings);
    EXPECT_EQ(s.phase, f64::PHASE_DONE);
    EXPECT_FALSE(s.hit);
}

// The ball on the floor, and the ball alone, seen from above at a slant.
scene::Scene ballScene(bool floor) {
    scene::Scene s = test::ballOnTheFloor();
    s.environment.ground.enabled = floor;
    s.camera.elevation = 20.0;
    s.camera.distance = 7.0;
    s.lights.clear();
    return s;
}

TEST(EmptyMarch, FindsTheSurfacesTheSteppingMarchFindsInFewerSamples) {
    for (bool floor : {true, false}) {
        program::Program program = program::compileScene(ballScene(floor), {kWidth, kHeight, 1});
        f64::TraceSettings settings = test::traceSettingsOf(program);
        ASSERT_NE(settings.boundsUse & f64::BOUNDS_SKIP_MARCH, 0) << "a ball has bounds";
        test::TracedProgram skipping(program),
            stepping(test::withBoundsUse(program, settings.boundsUse & ~f64::BOUNDS_SKIP_MARCH));
        long skippingSteps = 0, steppingSteps = 0, hits = 0, untouched = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                f64::SampleResult a = skipping.at(x, y), b = stepping.at(x, y);
                ASSERT_EQ(a.hit, b.hit) << x << ", " << y << " floor " << floor;
                skippingSteps += a.evaluations;
                steppingSteps += b.evaluations;
                if (!a.hit) {
                    untouched += a.evaluations == 0 ? 1 : 0;
                    continue;
                }
                ++hits;
                // the same surface point, to within the hit epsilon's reach along the ray
                double slack = 4.0 * std::max(settings.epsilon, settings.epsilonPerDistance * b.t);
                EXPECT_NEAR(a.t, b.t, slack) << x << ", " << y << " floor " << floor;
            }
        }
        EXPECT_GT(hits, kWidth * kHeight / 20);
        // without a floor, the rays that miss the ball's bounding sphere take no sample
        if (!floor) {
            EXPECT_GT(untouched, kWidth * kHeight / 2);
        }
        EXPECT_LT(3 * skippingSteps, 2 * steppingSteps)
            << "floor " << floor << ": " << skippingSteps << " against " << steppingSteps;
    }
}

}  // namespace
}  // namespace sdfwb
