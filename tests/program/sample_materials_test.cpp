// Program::samplesReadMaterials decides whether the CPU backend may evaluate
// the march, normal, AO and shadow samples for their distances only: it must
// say yes where no such sample reads a material and no where one does, and
// follow material edits, which change parameters and not the program's
// structure.

#include <gtest/gtest.h>

#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

program::Program compiledScene(const std::string& relative) {
    scene::Scene s = scene::loadSceneFile(test::sourceDir() + "/scenes/" + relative);
    return program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
}

TEST(SamplesReadMaterials, NotInAnOpaqueSceneWithoutBumpMaps) {
    EXPECT_FALSE(compiledScene("default.json").samplesReadMaterials());
}

// Shadows are tinted by transparent occluders, and an eye inside glass is
// told by the transparency at the first sample.
TEST(SamplesReadMaterials, WhereAMaterialTransmits) {
    EXPECT_TRUE(compiledScene("tutorial/09_glass.json").samplesReadMaterials());
}

// The normal's samples carry the bump height.
TEST(SamplesReadMaterials, WhereAProceduralBumpMapIs) {
    EXPECT_TRUE(compiledScene("tutorial/13_bump_map.json").samplesReadMaterials());
}

TEST(SamplesReadMaterials, FollowsAnEditedTransparency) {
    scene::Scene s = scene::loadSceneFile(test::sourceDir() + "/scenes/default.json");
    ASSERT_FALSE(s.materials.empty());
    program::Program before = program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
    s.materials.back().transparency = 0.25;
    program::Program after = program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
    EXPECT_FALSE(before.samplesReadMaterials());
    EXPECT_TRUE(after.samplesReadMaterials());
}

}  // namespace
}  // namespace sdfwb
