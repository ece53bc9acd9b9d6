// A floor far from the scene's objects is shaded as the plane it is
// (tracer.glsl's beginNormal and beginOcclusion, tracing "bounded"): where
// nothing but the ground lies within the normal's or the occlusion's reach
// of a hit, the tracer takes the plane's normal and its want of occlusion
// instead of sampling them. The image is the one the samples of an exact
// field give; only the count of evaluations changes. A ground with a bump
// map keeps its samples.

#include <random>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/interpreter.h"
#include "image/compare.h"
#include "image/image.h"
#include "program/compile_scene.h"
#include "scene/scene.h"
#include "scene/scene_json.h"
#include "support/ball_on_the_floor.h"
#include "support/scene_files.h"
#include "support/traced_program.h"

namespace sdfwb {
namespace {

using glm::dvec3;
namespace f64 = cpu::f64;

constexpr int kWidth = 64, kHeight = 36;
constexpr int kAllBoundsUses = f64::BOUNDS_END_SHADOW_RAYS | f64::BOUNDS_SKIP_MARCH | f64::BOUNDS_FLAT_GROUND;

// A hit at `point` over the plane y = 0, in the phase that samples around it.
f64::TraceState hitAt(dvec3 point, double epsilon, int phase) {
    f64::TraceState s = f64::traceBegin(f64::Ray(point, dvec3(0, -1, 0)));
    s.hit = true;
    s.hitPoint = point;
    s.hitEpsilon = epsilon;
    s.phase = phase;
    s.occlusion = point.y;  // the field at the hit, which the normal's probe reads (tracePoint)
    s.normalSum = dvec3(0, 4.0 * epsilon, 0);
    s.normal = dvec3(0, 1, 0);
    s.offsetScale = 1.0;
    return s;
}

// Whether a hit takes its phase's samples: the normal's (beginNormal, as the
// march that reached it begins them) or the occlusion's (beginOcclusion).
bool takesSamples(const f64::TraceState& hit, const f64::TraceSettings& settings) {
    if (hit.phase == f64::PHASE_NORMAL) {
        f64::TraceState march = f64::traceBegin(f64::Ray(hit.hitPoint, dvec3(0, -1, 0)));
        f64::Sample field{hit.hitPoint.y, hit.hitPoint.y, f64::Material{}};
        return f64::beginNormal(march, field, hit.hitEpsilon, settings).phase == f64::PHASE_NORMAL;
    }
    return f64::beginOcclusion(hit, settings).phase == f64::PHASE_AO;
}

// Where the normal and the occlusion would take their samples around a hit
// (tracePoint), the skip is taken only if the plane is nearer every one of
// them than the bounding sphere, which holds every other surface: the
// samples would have read the plane alone.
TEST(FlatGround, IsTakenOnlyWhereThePlaneIsNearerEverySampleThanTheBounds) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    int taken[2] = {0, 0};
    for (int i = 0; i < 4000; ++i) {
        f64::TraceSettings settings{};
        settings.boundsUse = f64::BOUNDS_FLAT_GROUND;
        settings.boundsCenter = dvec3(unit(random), 1.0 + unit(random), unit(random)) * 3.0;
        settings.boundsRadius = 0.2 + 2.0 * fraction(random);
        settings.aoSamples = 1 + i % 6;
        settings.aoDistance = 2.0 * fraction(random);
        double epsilon = 1e-3 * (1.0 + 10.0 * fraction(random));
        // on the plane, within epsilon of it, or above it where a ray out of steps stopped
        double height = epsilon * (i % 4 == 0 ? 20.0 * fraction(random) : unit(random));
        dvec3 point(8.0 * unit(random), height, 8.0 * unit(random));
        for (int phase : {f64::PHASE_NORMAL, f64::PHASE_AO}) {
            f64::TraceState s = hitAt(point, epsilon, phase);
            if (takesSamples(s, settings)) continue;
            ++taken[phase == f64::PHASE_AO];
            int samples = phase == f64::PHASE_AO ? settings.aoSamples : 5;  // the normal's four and its probe
            for (s.counter = 0; s.counter < samples; ++s.counter) {
                dvec3 q = f64::tracePoint(s, f64::Light{}, settings);
                double toBounds = glm::length(q - settings.boundsCenter) - settings.boundsRadius;
                ASSERT_GT(toBounds, q.y) << "case " << i << " phase " << phase << " sample " << s.counter;
            }
        }
    }
    EXPECT_GT(taken[0], 1000);
    EXPECT_GT(taken[1], 1000);
    f64::TraceSettings off{};
    off.boundsCenter = dvec3(0, 100, 0);
    f64::TraceState s = hitAt(dvec3(0), 1e-3, f64::PHASE_NORMAL);
    EXPECT_TRUE(takesSamples(s, off)) << "the bit is off";
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

class EverySceneFloor : public ::testing::TestWithParam<test::SceneFile> {};

// Every shipped scene, its floor shaded as a plane or sampled: the same
// display colours to within 1/255, what float rounding of the samples moves
// (a loose field's false occlusion near the floor would show here), and no
// more evaluations.
TEST_P(EverySceneFloor, LooksTheSameWithItsFloorShadedAsAPlane) {
    scene::Scene s = scene::loadSceneFile(GetParam().path());
    program::Program p = program::compileScene(s, {.width = 48, .height = 27, .aa = 1});
    int boundsUse = test::traceSettingsOf(p).boundsUse;
    if ((boundsUse & f64::BOUNDS_FLAT_GROUND) == 0) return;
    render::RenderOutcome planar = cpu::renderCpu(p),
                          sampled = cpu::renderCpu(test::withBoundsUse(p, boundsUse & ~f64::BOUNDS_FLAT_GROUND));
    EXPECT_LE(image::compareImages(planar.frame.color, sampled.frame.color).maxAbs, 1.0);
    EXPECT_LE(image::frameStats(planar.frame).meanEvaluations, image::frameStats(sampled.frame).meanEvaluations);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EverySceneFloor, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const ::testing::TestParamInfo<test::SceneFile>& info) { return info.param.testName(); });

}  // namespace
}  // namespace sdfwb
