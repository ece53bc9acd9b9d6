// Pruned fields equal the whole program's, bit for bit, everywhere inside the
// grid: on every shipped scene, the molecule and the generated large scenes.

#include <random>
#include <set>
#include <string>
#include <utility>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "prune/prune_grid.h"
#include "scene/scene_json.h"
#include "sdf/shared.h"
#include "support/large_scenes.h"
#include "support/scene_files.h"

namespace sdfwb {
namespace t32 = cpu::f32;

namespace {

struct Mismatch {
    int points = 0;
    int inside = 0;
    int distance = 0;  // points where d or step differ
    int material = 0;  // points where the material differs by more than 1e-6
    // Outside the grid, points where the ground is nearer than the bound:
    // its material there must be the whole program's (texture included).
    int outsideOnGround = 0;
    int groundMaterial = 0;
};

bool materialsClose(const t32::Material& a, const t32::Material& b) {
    auto close3 = [](glm::vec3 x, glm::vec3 y) { return glm::all(glm::lessThanEqual(glm::abs(x - y), glm::vec3(1e-6f))); };
    return close3(a.ambient, b.ambient) && close3(a.diffuse, b.diffuse) && close3(a.specular, b.specular) &&
           close3(a.emission, b.emission) && std::abs(a.shininess - b.shininess) <= 1e-6f;
}

// Samples points in the grid's box, and just around it, and compares.
Mismatch compareFields(const program::Program& program, int count) {
    Mismatch m;
    std::shared_ptr<const prune::PruneGrid> grid = prune::buildPruneGrid(program, 0);
    if (!grid) return m;
    std::vector<t32::vec4> params;
    for (const glm::dvec4& v : program.params) params.push_back(t32::vec4(v));
    for (const glm::dvec4& v : grid->extraParams) params.push_back(t32::vec4(v));
    t32::Scratch scratch(program);
    glm::dvec3 size = glm::dvec3(grid->dims) * grid->cellSize;
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> unit(-0.05, 1.05);
    for (int i = 0; i < count; ++i) {
        glm::vec3 p(grid->origin + size * glm::dvec3(unit(random), unit(random), unit(random)));
        t32::Sample full = t32::mapProgram(program, params.data(), scratch, p);
        t32::Sample pruned = t32::fieldAt(program, grid.get(), params.data(), scratch, p);
        ++m.points;
        if (prune::leafIndexAt(*grid, p) == grid->outsideLeaf) {
            // outside: the distance to the bounds, not the field, unless the ground is nearer
            if (program.groundStart >= 0 && pruned.d == full.d) {
                ++m.outsideOnGround;
                if (!materialsClose(pruned.material, full.material)) ++m.groundMaterial;
            }
            continue;
        }
        ++m.inside;
        if (!(pruned.d == full.d && pruned.step == full.step)) ++m.distance;
        if (!materialsClose(pruned.material, full.material)) ++m.material;
    }
    return m;
}

class EveryScene : public ::testing::TestWithParam<test::SceneFile> {};

TEST_P(EveryScene, PrunedFieldEqualsTheWholeProgramInsideTheGrid) {
    program::Program program = program::compileScene(scene::loadSceneFile(GetParam().path()));
    Mismatch m = compareFields(program, 3000);
    EXPECT_EQ(m.distance, 0) << m.inside << " points inside the grid";
    EXPECT_EQ(m.material, 0) << m.inside << " points inside the grid";
    EXPECT_EQ(m.groundMaterial, 0) << m.outsideOnGround << " points outside the grid on the ground";
}

// The field outside the grid unites the ground with the bound, and a textured
// ground there keeps its texture and bump map.
TEST(OutsideTheGrid, TheGroundKeepsItsTexture) {
    program::Program program =
        program::compileScene(scene::loadSceneFile(test::SceneFile{"showcase/courtyard.json"}.path()));
    Mismatch m = compareFields(program, 3000);
    EXPECT_GT(m.outsideOnGround, 20);
    EXPECT_EQ(m.groundMaterial, 0) << m.outsideOnGround << " points outside the grid on the ground";
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const auto& info) { return info.param.testName(); });

struct LargeCase {
    std::string name;
    scene::Scene (*make)();
};

class LargeScene : public ::testing::TestWithParam<LargeCase> {};

TEST_P(LargeScene, PrunedFieldEqualsTheWholeProgramAndIsShort) {
    program::Program program = program::compileScene(GetParam().make());
    std::shared_ptr<const prune::PruneGrid> grid = prune::buildPruneGrid(program);
    ASSERT_TRUE(grid);
    Mismatch m = compareFields(program, 2000);
    EXPECT_GT(m.inside, m.points / 2);
    EXPECT_EQ(m.distance, 0);
    EXPECT_EQ(m.material, 0);
    // the hierarchy keeps the cells' lists far shorter than the whole program
    // (a mean over cells: equal lists share one leaf, so leaves alone would
    // weigh the rare long lists as much as the common short ones)
    long cells = 0, instructions = 0;
    for (int node : grid->nodes) {
        if (node < 0) continue;
        ++cells;
        instructions += grid->leaves[static_cast<size_t>(node)].count;
    }
    double mean = static_cast<double>(instructions) / static_cast<double>(cells);
    EXPECT_LT(mean, program.code.size() / 4.0) << "longest leaf " << grid->longestLeaf;
    // equal lists share one leaf: no two leaves hold the same list
    std::set<std::pair<int, std::string>> lists;
    for (const prune::PruneLeaf& leaf : grid->leaves) {
        const char* first = reinterpret_cast<const char*>(grid->code.data() + leaf.offset);
        lists.emplace(leaf.result, std::string(first, static_cast<size_t>(leaf.count) * sizeof(program::Instruction)));
    }
    EXPECT_EQ(lists.size(), grid->leaves.size());
    EXPECT_LT(grid->leaves.size(), static_cast<size_t>(cells));
}

INSTANTIATE_TEST_SUITE_P(
    Generated, LargeScene,
    ::testing::Values(LargeCase{"molecule100", [] { return test::moleculeScene("molecule_100"); }},
                      LargeCase{"molecule100_hard", [] { return test::hardVariant(test::moleculeScene("molecule_100")); }},
                      LargeCase{"city400", [] { return test::cityScene(400); }},
                      LargeCase{"capsules300", [] { return test::capsuleChainScene(300); }},
                      LargeCase{"nested", [] { return test::nestedGroupsScene(27, 8); }}),
    [](const auto& info) { return info.param.name; });

// The window's GL viewport asks without waiting: not built yet, then the
// cached grid once a build is done (no clock: the blocking call waits for it).
TEST(PruneGrid, IfBuiltNeverWaitsAndThenReturnsTheCachedGrid) {
    program::Program program = program::compileScene(test::cityScene(100), {.width = 24, .height = 14, .aa = 1});
    EXPECT_FALSE(prune::pruneGridIfBuilt(program).has_value());
    std::shared_ptr<const prune::PruneGrid> grid = prune::pruneGridFor(program);
    ASSERT_TRUE(grid);
    std::optional<std::shared_ptr<const prune::PruneGrid>> ready = prune::pruneGridIfBuilt(program);
    ASSERT_TRUE(ready.has_value());
    EXPECT_EQ(*ready, grid);
    // a scene without a grid answers null, not "not yet", once built
    program::Program small = program::compileScene(test::moleculeScene("molecule_10"));
    prune::pruneGridFor(small);
    EXPECT_EQ(prune::pruneGridIfBuilt(small), std::optional<std::shared_ptr<const prune::PruneGrid>>(nullptr));
}

TEST(PruneGrid, NoPruneSwitchSmallAndUnboundedScenesHaveNoGrid) {
    EXPECT_FALSE(prune::buildPruneGrid(program::compileScene(test::moleculeScene("molecule_10"))));
    scene::Scene s = test::moleculeScene("molecule_100");
    EXPECT_TRUE(prune::buildPruneGrid(program::compileScene(s)));
    EXPECT_FALSE(prune::buildPruneGrid(program::compileScene(s, {.prune = false})));
    s.root.children.push_back(scene::Node::make(scene::NodeKind::Plane));
    EXPECT_FALSE(prune::buildPruneGrid(program::compileScene(s)));
}

// The image is the same bit for bit: inside the grid the field is, and the
// eye is inside the grid, so primary rays never start on the outside bound.
TEST(PruneGrid, PrunedRenderEqualsTheUnprunedOne) {
    for (const scene::Scene& s : {test::moleculeScene("molecule_100"), test::hardVariant(test::moleculeScene("molecule_100")),
                                  test::nestedGroupsScene(8, 16)}) {
        program::CompileOptions options{.width = 96, .height = 54, .aa = 1};
        program::Program pruned = program::compileScene(s, options);
        ASSERT_TRUE(prune::buildPruneGrid(pruned));
        options.prune = false;
        image::Frame a = cpu::renderCpu(pruned).frame, b = cpu::renderCpu(program::compileScene(s, options)).frame;
        EXPECT_EQ(a.color.rgb, b.color.rgb) << s.name;
        EXPECT_EQ(a.depth, b.depth) << s.name;
    }
}

}  // namespace
}  // namespace sdfwb
