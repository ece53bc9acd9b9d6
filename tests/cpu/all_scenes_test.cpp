// Every shipped scene renders on the CPU backend without NaN or infinite pixels,
// and one without mirrors or glass renders as it would through the ray tree.

#include <cmath>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/scene_files.h"

namespace sdfwb {
namespace {

class EveryScene : public ::testing::TestWithParam<test::SceneFile> {};

// Two programs of one scene render the same bits: colours, depths, step and
// evaluation counts.
void expectSameRender(const program::Program& a, const program::Program& b) {
    render::RenderOutcome x = cpu::renderCpu(a), y = cpu::renderCpu(b);
    EXPECT_EQ(x.frame.color.rgb, y.frame.color.rgb);
    EXPECT_EQ(x.frame.depth, y.frame.depth);
    EXPECT_EQ(x.frame.steps, y.frame.steps);
    EXPECT_EQ(x.frame.evaluations, y.frame.evaluations);
}

TEST_P(EveryScene, RendersFinitePixels) {
    scene::Scene s = scene::loadSceneFile(GetParam().path());
    program::Program p = program::compileScene(s, {.width = 64, .height = 36, .aa = 1});
    render::RenderOutcome outcome = cpu::renderCpu(p);
    ASSERT_FALSE(outcome.cancelled);
    size_t nonFinite = 0;
    for (float v : outcome.frame.color.rgb) nonFinite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(nonFinite, 0u);
}

// With k_ps = k_t = 0 everywhere (or max_depth 0) a scene compiles no ray
// tree; the tree's code forced on must change no bit of what it renders.
TEST_P(EveryScene, WithoutMirrorsOrGlassRendersAsThroughTheRayTree) {
    scene::Scene s = scene::loadSceneFile(GetParam().path());
    program::Program p = program::compileScene(s, {.width = 32, .height = 18, .aa = 1});
    if (p.secondaryRays) return;  // a scene with mirrors or glass: the tree is its own
    program::Program tree = p;
    tree.secondaryRays = true;
    expectSameRender(p, tree);
}

// The march, normal, AO and shadow evaluations of a scene whose materials
// none of them reads carry distances only (cpu/interpreter.inl); the hit's
// material comes from the material phase either way. Carrying materials
// through every evaluation must change no bit of the image, its depths or
// the evaluation counts.
TEST_P(EveryScene, DistanceOnlyEvaluationsRenderAsWithMaterials) {
    scene::Scene s = scene::loadSceneFile(GetParam().path());
    program::Program p = program::compileScene(s, {.width = 48, .height = 27, .aa = 1});
    program::Program materials = p;
    materials.distanceOnlyEvaluation = false;
    expectSameRender(p, materials);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const ::testing::TestParamInfo<test::SceneFile>& info) { return info.param.testName(); });

}  // namespace
}  // namespace sdfwb
