// With tracing "bounded" (the default) the march takes the ground plane along the ray
// (tracer.glsl's groundAhead): rays over an open floor land on it in a step
// or two, exactly, where a plane primitive at the same height, or the ground
// with tracing "plain", is closed in on geometrically; rays towards the
// sky are not held back by the floor; the hits are those of the plane
// primitive, and a floor just past max distance is seen as it was.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene.h"
#include "support/ball_on_the_floor.h"
#include "support/traced_program.h"

namespace sdfwb {
namespace {

using glm::dvec3;
namespace f64 = cpu::f64;

constexpr int kWidth = 64, kHeight = 36;

// The ball on the floor, seen from above at a slant.
scene::Scene ballOnTheFloor() {
    scene::Scene s = test::ballOnTheFloor();
    s.camera.elevation = 15.0;
    s.camera.distance = 8.0;
    s.render.maxDistance = 60.0;
    return s;
}

// The same floor as a plane primitive, which the march treats like any surface.
scene::Scene withPlanePrimitive(scene::Scene s) {
    s.environment.ground.enabled = false;
    s.root.children.push_back(scene::Node::make(scene::NodeKind::Plane));
    return s;
}

struct Traced : test::TracedProgram {
    explicit Traced(const scene::Scene& s) : test::TracedProgram(s, kWidth, kHeight) {}
};

TEST(GroundStep, FloorRaysLandOnThePlaneInAFractionOfTheSteps) {
    for (double relaxation : {1.0, 1.6}) {
        scene::Scene s = ballOnTheFloor();
        s.render.stepRelaxation = relaxation;
        scene::Scene sphereTraced = s;
        sphereTraced.render.tracing = scene::Tracing::Plain;
        Traced ground(s), plane(withPlanePrimitive(s)), sphere(sphereTraced);
        long groundSteps = 0, planeSteps = 0, sphereSteps = 0, floorPixels = 0, disagreements = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                f64::SampleResult g = ground.at(x, y), q = plane.at(x, y);
                disagreements += g.hit != q.hit;
                f64::Ray ray = ground.ray(x, y);
                dvec3 hit = dvec3(ray.origin + ray.direction * g.t) + scene::cameraFrame(s.camera).eye;
                bool onTheFloor = g.hit && q.hit && std::abs(hit.y) < 1e-6 * g.t;
                if (!onTheFloor) continue;
                ++floorPixels;
                groundSteps += g.steps;
                planeSteps += q.steps;
                sphereSteps += sphere.at(x, y).steps;
                // the plane primitive stops within epsilon of the floor
                const program::TraceParams& trace = ground.program.trace;
                double slack = std::max(trace.epsilon, trace.epsilonPerDistance * g.t) / -ray.direction.y;
                EXPECT_NEAR(q.t, g.t, 2.0 * slack) << x << ", " << y;
            }
        }
        EXPECT_GT(floorPixels, kWidth * kHeight / 3) << relaxation;
        EXPECT_LE(disagreements, kWidth * kHeight / 200) << relaxation;  // silhouettes, stepped otherwise
        EXPECT_LE(4 * groundSteps, planeSteps) << relaxation << ": " << groundSteps << " against " << planeSteps;
        // tracing "plain" steps towards the floor as towards any surface
        EXPECT_LE(4 * groundSteps, sphereSteps) << relaxation << ": " << groundSteps << " against " << sphereSteps;
    }
}

TEST(GroundStep, RaysTowardsTheSkyAreNotHeldBackByTheFloor) {
    scene::Scene s = ballOnTheFloor();
    s.camera.target = dvec3(0, 2.5, 0);
    s.camera.elevation = -10.0;  // from below the ball's top, looking up past it
    s.camera.distance = 4.0;
    scene::Scene noGround = s;
    noGround.environment.ground.enabled = false;
    Traced ground(s), bare(noGround);
    int upwards = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!(ground.ray(x, y).direction.y > 0.0)) continue;
            ++upwards;
            f64::SampleResult g = ground.at(x, y), b = bare.at(x, y);
            EXPECT_EQ(g.hit, b.hit) << x << ", " << y;
            EXPECT_EQ(g.steps, b.steps) << x << ", " << y;
            EXPECT_EQ(g.t, b.t) << x << ", " << y;
        }
    }
    EXPECT_GT(upwards, kWidth * kHeight / 2);
}

// A floor just past max distance was closed in on step by step until within
// epsilon of it: a hit when that happened before max distance, as it still
// does with tracing "plain". One more sample at max distance keeps
// that, where a step onto the plane would end the ray past max distance
// unchecked; the sample lands on max distance exactly, after the march's
// skip over the empty space (emptyMarchAhead) and, without that skip, after
// steps that other surfaces limited (a ball beside the ray).
TEST(GroundStep, AFloorJustPastMaxDistanceIsSeenAsBefore) {
    for (bool ball : {false, true}) {
        scene::Scene s = ballOnTheFloor();
        s.root.children[0].set("offset", dvec3(-1.6, 1, 0));
        if (!ball) s.root.children.clear();
        s.render.epsilonMode = scene::EpsilonMode::Absolute;
        s.render.epsilon = 0.01;
        s.render.maxDistance = 37.3;
        const int x = kWidth / 2, y = kHeight / 4;  // below the centre: a ray heading down
        f64::Ray ray = Traced(s).ray(x, y);
        ASSERT_LT(ray.direction.y, 0.0);
        dvec3 eye = scene::cameraFrame(s.camera).eye;
        // the floor's height where the ray meets it at distance t
        auto floorMetAt = [&](double t) { return eye.y + ray.direction.y * t; };
        double slack = s.render.epsilon / -ray.direction.y;  // distance along the ray per epsilon of height
        for (auto [past, seen] : {std::pair{0.5, true}, std::pair{2.0, false}}) {
            s.environment.ground.height = floorMetAt(s.render.maxDistance + past * slack);
            scene::Scene sphereTraced = s;
            sphereTraced.render.tracing = scene::Tracing::Plain;
            Traced skipping(s);
            test::TracedProgram stepping(test::withBoundsUse(skipping.program, f64::BOUNDS_END_SHADOW_RAYS));
            f64::SampleResult exact = skipping.at(x, y), stepped = stepping.at(x, y);
            f64::SampleResult sphere = Traced(sphereTraced).at(x, y);
            EXPECT_EQ(exact.hit, seen) << past << " epsilon past max distance, ball " << ball;
            EXPECT_EQ(stepped.hit, seen) << past << " epsilon past max distance, ball " << ball;
            EXPECT_EQ(sphere.hit, seen) << past << " epsilon past max distance, ball " << ball;
            if (seen) {
                EXPECT_EQ(exact.t, s.render.maxDistance) << "ball " << ball;
                // with the ball, the empty space is skipped and the sample at
                // max distance is the only step; without it the scene has no
                // bounds, and a step onto the plane comes first
                EXPECT_EQ(exact.steps, ball ? 1 : 2) << "ball " << ball;
                EXPECT_EQ(stepped.t, s.render.maxDistance) << "ball " << ball;
                EXPECT_GT(stepped.steps, ball ? 2 : 1) << "ball " << ball;
            }
        }
    }
}

}  // namespace
}  // namespace sdfwb
