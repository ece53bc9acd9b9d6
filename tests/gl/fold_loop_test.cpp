// Large scenes on the GL backend (issue 10): a run of many children becomes
// one loop over the children the point's prune-grid cell keeps
// (gl/fold_run.h). The GL image must match the CPU backend's pruned one, with
// pruning off too, on flat smooth and hard unions, a city of boxes and
// nested groups; the shader text must not change when a parameter does.

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "gl/fold_run.h"
#include "gl/gl_renderer.h"
#include "gl/shader_generator.h"
#include "gl_test_support.h"
#include "image/compare.h"
#include "program/compile_scene.h"
#include "prune/prune_grid.h"
#include "support/large_scenes.h"

namespace sdfwb {
namespace {

TEST(FoldRun, FindsTheMoleculesChildrenAndLeavesOtherScenesAlone) {
    program::Program molecule = program::compileScene(test::moleculeScene("molecule_100"));
    std::optional<gl::FoldRun> run = gl::findFoldRun(molecule);
    ASSERT_TRUE(run);
    EXPECT_EQ(run->length, 3);   // translate, sphere, smooth union
    EXPECT_EQ(run->count, 99);   // every sphere but the first, which starts the accumulator
    ASSERT_TRUE(gl::findFoldRun(program::compileScene(test::hardVariant(test::moleculeScene("molecule_100")))));
    EXPECT_FALSE(gl::findFoldRun(program::compileScene(test::moleculeScene("molecule_10"))));  // under 16 children
}

TEST(FoldRun, ShaderTextDependsOnlyOnTheStructure) {
    scene::Scene s = test::moleculeScene("molecule_100");
    std::string before = gl::generateFragmentShader(program::compileScene(s));
    s.root.children[5].children[0].set("radius", 0.5);
    EXPECT_EQ(gl::generateFragmentShader(program::compileScene(s)), before);
}

class FoldLoopOnGl : public test::GlTest {
protected:
    // GL against the CPU backend at 64 x 36, AA 1, within the parity gate
    void expectParity(const scene::Scene& scene, bool prune, const std::string& name) {
        program::Program p = program::compileScene(scene, {.width = 64, .height = 36, .aa = 1, .prune = prune});
        gl::GlRenderer renderer(gl());
        image::Frame glFrame = renderer.render(p).frame;
        image::Frame cpuFrame = cpu::renderCpu(p).frame;
        image::Comparison c = image::compareImages(cpuFrame.color, glFrame.color);
        EXPECT_TRUE(image::passes(c, image::kParityThresholds))
            << name << ": max " << c.maxAbs << "/255, " << c.percentAbove1 << " % above 1/255";
        EXPECT_LE(c.maxAbs, 1.0) << name;
        double covered = 0;
        for (float v : glFrame.coverage) covered += v;
        EXPECT_GT(covered, 0.0) << name << ": nothing drawn";
    }
};

TEST_F(FoldLoopOnGl, MatchesTheCpuBackendPrunedAndWhole) {
    scene::Scene molecule = test::moleculeScene("molecule_100");
    ASSERT_TRUE(prune::pruneGridFor(program::compileScene(molecule, {.width = 64, .height = 36, .aa = 1})));
    expectParity(molecule, true, "molecule 100");
    expectParity(molecule, false, "molecule 100, --no-prune");
    expectParity(test::hardVariant(molecule), true, "molecule 100, hard union");
    expectParity(test::cityScene(100), true, "city of 100 boxes");
    expectParity(test::nestedGroupsScene(4, 16), true, "nested groups");
}

}  // namespace
}  // namespace sdfwb
