// The grid cache: what an edit rebuilds, one build for callers at once, and
// renders that do not wait for it.

#include <algorithm>
#include <memory>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "program/compile_scene.h"
#include "prune/grid_edits.h"
#include "prune/prune_grid.h"
#include "support/large_scenes.h"

namespace sdfwb {
namespace {

const program::Instruction& firstWith(const program::Program& program, bool (*wanted)(const program::Instruction&)) {
    auto found = std::find_if(program.code.begin(), program.code.end(), wanted);
    EXPECT_NE(found, program.code.end());
    return *found;
}

// Pruning decides on distances and a leaf reads every parameter when it runs,
// so a colour edit keeps the grid and the image stays the unpruned one; a
// moved primitive builds a new grid.
TEST(PruneGridCache, AColourEditKeepsTheGridAndAMoveBuildsANewOne) {
    program::Program program =
        program::compileScene(test::moleculeScene("molecule_100"), {.width = 96, .height = 54, .aa = 1});
    std::shared_ptr<const prune::PruneGrid> grid = prune::pruneGridFor(program);
    ASSERT_TRUE(grid);
    image::Frame before = cpu::renderCpu(program).frame;

    program::Program recoloured = program;
    int material = firstWith(program, [](const program::Instruction& in) { return in.material >= 0; }).material;
    glm::dvec4& diffuse = recoloured.params[static_cast<size_t>(material + 1)];
    diffuse = glm::dvec4(0.9, 0.2, 0.1, diffuse.w);
    long built = prune::pruneGridsBuilt();
    EXPECT_EQ(prune::pruneGridFor(recoloured), grid);
    EXPECT_EQ(prune::pruneGridsBuilt(), built);
    program::Program unpruned = recoloured;
    unpruned.prune = false;
    image::Frame after = cpu::renderCpu(recoloured).frame, reference = cpu::renderCpu(unpruned).frame;
    EXPECT_EQ(after.color.rgb, reference.color.rgb);
    EXPECT_EQ(after.depth, reference.depth);
    EXPECT_NE(after.color.rgb, before.color.rgb);  // the edit is seen

    program::Program moved = program;
    int offset = firstWith(program, [](const program::Instruction& in) {
                     return in.op == program::Opcode::Translate && in.param >= 0;
                 }).param;
    moved.params[static_cast<size_t>(offset)].x += 0.01;
    built = prune::pruneGridsBuilt();
    EXPECT_NE(prune::pruneGridFor(moved), grid);
    EXPECT_EQ(prune::pruneGridsBuilt(), built + 1);
}

// keepsPruneGrids, which the window's preview trusts to expect a grid: the
// edit it keeps builds no grid; the edits it does not keep include a moved
// sphere, a camera move (programs are compiled relative to the eye), a
// light's softness and the AO distance, each of which builds one.
TEST(PruneGridCache, TheEditsSaidToKeepTheGridsBuildNone) {
    const scene::Scene before = test::moleculeScene("molecule_100");
    const program::CompileOptions size{.width = 96, .height = 54, .aa = 1};
    ASSERT_TRUE(prune::pruneGridFor(program::compileScene(before, size)));
    ASSERT_FALSE(before.lights.empty());
    scene::Scene relit = before;
    relit.lights[0].direction = glm::dvec3(-0.3, 0.9, 0.1);
    relit.lights[0].color = glm::dvec3(0.2, 0.5, 1.0);
    EXPECT_TRUE(prune::keepsPruneGrids(before, relit));
    long built = prune::pruneGridsBuilt();
    prune::pruneGridFor(program::compileScene(relit, size));
    EXPECT_EQ(prune::pruneGridsBuilt(), built);

    scene::Scene moved = before, orbited = before, softer = before, widerAo = before;
    moved.root.children[3].set("offset", glm::dvec3(0.5, 0.25, 0.125));
    orbited.camera.azimuth += 40;
    softer.lights[0].softness *= 2;
    widerAo.render.aoDistance *= 2;
    int edit = 0;
    for (const scene::Scene& changed : {moved, orbited, softer, widerAo}) {
        SCOPED_TRACE(edit++);
        EXPECT_FALSE(prune::keepsPruneGrids(before, changed));
        built = prune::pruneGridsBuilt();
        prune::pruneGridFor(program::compileScene(changed, size));
        EXPECT_EQ(prune::pruneGridsBuilt(), built + 1);
    }
}

// Tiles, the progressive viewport and the background build ask at once: the
// callers of a grid nobody has built share one build.
TEST(PruneGridCache, CallersAtOnceShareOneBuild) {
    program::Program program = program::compileScene(test::cityScene(150), {.width = 24, .height = 14, .aa = 1});
    long built = prune::pruneGridsBuilt();
    constexpr int kCallers = 4;
    std::vector<std::shared_ptr<const prune::PruneGrid>> grids(kCallers);
    {
        std::vector<std::jthread> callers;
        for (int i = 0; i < kCallers; ++i) {
            callers.emplace_back([&, i] { grids[static_cast<size_t>(i)] = prune::pruneGridFor(program); });
        }
    }
    EXPECT_EQ(prune::pruneGridsBuilt(), built + 1);
    ASSERT_TRUE(grids[0]);
    for (const auto& grid : grids) EXPECT_EQ(grid, grids[0]);
}

// The window's previews do not wait for a grid (RenderControl::
// waitForPruneGrid): without it they evaluate the whole program, which gives
// the same image (the step counts differ outside the grid, where it marches
// on a bound), and the grid's build they start is the one a later render
// waits for.
TEST(PruneGridCache, ARenderThatDoesNotWaitForTheGridDrawsTheSameImage) {
    program::Program program =
        program::compileScene(test::moleculeScene("molecule_100"), {.width = 48, .height = 27, .aa = 1});
    int offset = firstWith(program, [](const program::Instruction& in) {
                     return in.op == program::Opcode::Translate && in.param >= 0;
                 }).param;
    program.params[static_cast<size_t>(offset)].y += 0.02;  // a grid no other test has built
    long built = prune::pruneGridsBuilt();
    render::RenderControl preview;
    preview.waitForPruneGrid = false;
    image::Frame drawn = cpu::renderCpu(program, preview).frame;
    image::Frame waited = cpu::renderCpu(program).frame;
    EXPECT_EQ(prune::pruneGridsBuilt(), built + 1);
    EXPECT_EQ(drawn.color.rgb, waited.color.rgb);
    EXPECT_EQ(drawn.depth, waited.depth);
}

}  // namespace
}  // namespace sdfwb
