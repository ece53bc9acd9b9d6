// Rendering for interactive callers: a render spread over many short calls
// gives the same frame as one render() call, and a program built and warmed
// up by the worker (a shared context on another thread) is adopted without
// compiling again.

#include <gtest/gtest.h>

#include "gl/program_builder.h"
#include "gl/progressive_render.h"
#include "gl_test_support.h"
#include "glcontext/gl_debug.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/region_check.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

program::Program smallDefault(int aa) {
    scene::Scene s = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json");
    return program::compileScene(s, {120, 70, aa});
}

class ProgressiveRenderTest : public test::GlTest {};

TEST_F(ProgressiveRenderTest, ManySmallStepsGiveTheFrameOfOneRender) {
    gl::GlRenderer renderer(gl());
    program::Program p = smallDefault(2);
    render::RenderOutcome whole = renderer.render(p, {.tileSize = 32});
    gl::GlProgressiveRender progressive(renderer, p, {.tileSize = 32});
    int calls = 0, tiles = 0;
    while (!progressive.done()) {
        tiles += static_cast<int>(progressive.advance(0.0).size());  // one draw per call
        ++calls;
    }
    EXPECT_EQ(tiles, 4 * 3);                   // 120x70 in 32-pixel tiles
    EXPECT_EQ(calls, tiles * 4);               // AA 2: four sub-sample draws per tile
    EXPECT_DOUBLE_EQ(progressive.progress(), 1.0);
    EXPECT_EQ(progressive.frame().color.rgb, whole.frame.color.rgb);
    EXPECT_EQ(progressive.frame().steps, whole.frame.steps);
    EXPECT_EQ(progressive.frame().coverage, whole.frame.coverage);
}

TEST_F(ProgressiveRenderTest, ARegionHoldsTheWholeFramesPixelsAndNothingElse) {
    gl::GlRenderer renderer(gl());
    program::Program p = smallDefault(2);
    render::RenderOutcome whole = renderer.render(p, {.tileSize = 32});
    const render::TileRect region{37, 21, 50, 30};
    render::RenderOutcome part = renderer.render(p, {.tileSize = 16, .region = region});
    test::expectRegionOfFrame(whole.frame, part.frame, region);
    gl::GlProgressiveRender progressive(renderer, p, {.tileSize = 16, .region = render::TileRect{100, 60, 99, 99}});
    while (!progressive.done()) progressive.advance(0.0);
    test::expectRegionOfFrame(whole.frame, progressive.frame(), {100, 60, 20, 10});  // clipped to 120x70
}

// A GL error an earlier call left pending (the GUI's, sharing the context)
// is not this render's: it used to fail the viewport's GLSL render after the
// next edit, blamed on "GlProgressiveRender::draw".
TEST_F(ProgressiveRenderTest, AnErrorLeftByAnEarlierCallDoesNotFailTheDraw) {
    gl::GlRenderer renderer(gl());
    program::Program p = smallDefault(1);
    gl::GlProgressiveRender progressive(renderer, p, {});
    gl().Enable(0x7FFF);  // no such capability: GL_INVALID_ENUM
    EXPECT_NO_THROW(progressive.advance(0.0));
    EXPECT_EQ(glcontext::takeGlErrors(gl()), "");
}

TEST_F(ProgressiveRenderTest, WorkerBuiltProgramIsAdoptedWithoutACompile) {
    gl::GlRenderer renderer(gl());
    program::Program p = smallDefault(1);
    std::optional<gl::BuiltProgram> built;
    {
        gl::ProgramBuilder builder(context().createShared());
        builder.request(p);
        builder.request(p);  // a duplicate request is ignored
        builder.wait();
        EXPECT_FALSE(builder.busy());
        built = builder.take();
        ASSERT_TRUE(built);
        EXPECT_FALSE(builder.take());
    }
    ASSERT_TRUE(built->linked) << built->error;
    renderer.adoptProgram(built->program, std::move(built->linked));
    EXPECT_TRUE(renderer.hasProgram(p));
    render::RenderOutcome adopted = renderer.render(p);
    EXPECT_EQ(renderer.counters().compiles, 0);

    gl::GlRenderer fresh(gl());
    EXPECT_EQ(fresh.render(p).frame.color.rgb, adopted.frame.color.rgb);
    EXPECT_EQ(fresh.counters().compiles, 1);
}

}  // namespace
}  // namespace sdfwb
