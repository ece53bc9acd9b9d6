// Every shipped scene renders on the CPU backend without NaN or infinite pixels.

#include <cmath>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "support/scene_files.h"
#include "scene/scene_json.h"

namespace sdfwb {
namespace {

class EveryScene : public ::testing::TestWithParam<test::SceneFile> {};

TEST_P(EveryScene, RendersFinitePixels) {
    scene::Scene s = scene::loadSceneFile(GetParam().path());
    program::Program p = program::compileScene(s, {.width = 64, .height = 36, .aa = 1});
    render::RenderOutcome outcome = cpu::renderCpu(p);
    ASSERT_FALSE(outcome.cancelled);
    size_t nonFinite = 0;
    for (float v : outcome.frame.color.rgb) nonFinite += std::isfinite(v) ? 0 : 1;
    EXPECT_EQ(nonFinite, 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const ::testing::TestParamInfo<test::SceneFile>& info) { return info.param.testName(); });

}  // namespace
}  // namespace sdfwb
