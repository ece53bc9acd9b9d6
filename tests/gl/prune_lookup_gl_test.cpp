// The prune grid's cell lookup (sdf/glsl/prune_lookup.glsl) in GLSL on
// llvmpipe names the same leaf as the CPU backend's float lookup, at random
// points in and around the grid and on cell boundaries at every level: the
// backends must evaluate the same pruned instructions at every point.

#include <random>
#include <set>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"
#include "program/compile_scene.h"
#include "prune/prune_grid.h"
#include "sdf/glsl_sources.h"
#include "support/large_scenes.h"

namespace sdfwb {
namespace {

constexpr int kSide = 64;  // a 64 x 64 evaluation

class PruneLookupOnGl : public test::GlTest {};

TEST_F(PruneLookupOnGl, NamesTheLeafTheCpuNames) {
    program::Program program = program::compileScene(test::cityScene(100), {.width = 64, .height = 36, .aa = 1});
    std::shared_ptr<const prune::PruneGrid> grid = prune::buildPruneGrid(program);
    ASSERT_TRUE(grid);
    // node and leaf numbers pass through float textures exactly
    ASSERT_LT(grid->nodes.size(), size_t(1) << 24);

    std::mt19937 random(7);
    glm::dvec3 extent = glm::dvec3(grid->dims) * grid->cellSize;
    std::uniform_real_distribution<double> unit(-0.05, 1.05);
    std::uniform_int_distribution<int> boundary(0, 32 * 8);
    std::vector<float> points;
    std::vector<glm::vec3> cpuPoints;
    for (int i = 0; i < kSide * kSide; ++i) {
        glm::dvec3 p;
        for (int c = 0; c < 3; ++c) {
            // every other point on a boundary of a level-5 cell (1/32 of a root cell) on some axis
            p[c] = (i % 2 == 0 && (i / 2) % 3 == c) ? grid->origin[c] + boundary(random) * grid->cellSize / 32.0
                                                    : grid->origin[c] + unit(random) * extent[c];
        }
        glm::vec3 f(p);
        cpuPoints.push_back(f);
        points.insert(points.end(), {f.x, f.y, f.z, 0.0f});
    }
    std::vector<float> nodes(grid->nodes.begin(), grid->nodes.end());
    glm::vec4 frame(grid->lookupFrame()), dims(grid->lookupDims());
    std::vector<float> header = {frame.x, frame.y, frame.z, frame.w, dims.x, dims.y, dims.z, dims.w};

    std::string source = std::string(sdf::glslPrelude()) + std::string(sdf::glslLibrary()) +
                         "invariant evalResult;\n"
                         "uniform samplerBuffer inPoints;\nuniform samplerBuffer inNodes;\n"
                         "uniform samplerBuffer inGrid;\n"
                         "int PN(int i) { return int(texelFetch(inNodes, i).x); }\n" +
                         std::string(sdf::glslPruneLookup()) +
                         "void main() {\n"
                         "  vec3 p = xyz(texelFetch(inPoints, evalIndex()));\n"
                         "  evalResult = vec4(float(pruneLeafAt(p, texelFetch(inGrid, 0), texelFetch(inGrid, 1))));\n"
                         "}\n";
    glcontext::FragmentEvaluator evaluator(gl(), source);
    std::vector<glcontext::EvaluatorInput> inputs = {{"inPoints", 4, glcontext::InputLayout::Buffer, points},
                                                     {"inNodes", 1, glcontext::InputLayout::Buffer, nodes},
                                                     {"inGrid", 4, glcontext::InputLayout::Buffer, header}};
    std::vector<float> got = evaluator.evaluate(gl(), kSide, kSide, inputs);

    int outside = 0;
    std::set<int> leaves;
    for (int i = 0; i < kSide * kSide; ++i) {
        int expected = prune::leafIndexAt(*grid, cpuPoints[static_cast<size_t>(i)]);
        ASSERT_EQ(static_cast<int>(got[static_cast<size_t>(i) * 4]), expected) << "point " << i;
        outside += expected == grid->outsideLeaf ? 1 : 0;
        leaves.insert(expected);
    }
    // the points reach outside the grid and many cells of its split levels
    EXPECT_GT(outside, 0);
    EXPECT_GT(leaves.size(), size_t(500)) << grid->leaves.size() << " leaves";
}

}  // namespace
}  // namespace sdfwb
