// Program::materialReads says which material fields the CPU backend must
// carry through the tracer's evaluations (sdf/glsl/tracer.glsl,
// traceMaterialReads): the shading always, the transparency only where some
// material transmits, the bump height only where there is a procedural bump
// map. It follows material edits, which change parameters and not the
// program's structure.

#include <gtest/gtest.h>

#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "sdf/shared.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

namespace shared = sdf::f64;

program::Program compiledScene(const std::string& relative) {
    scene::Scene s = scene::loadSceneFile(test::sourceDir() + "/scenes/" + relative);
    return program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
}

TEST(MaterialReads, OnlyTheShadingInAnOpaqueSceneWithoutBumpMaps) {
    EXPECT_EQ(compiledScene("default.json").materialReads(), shared::MATERIAL_READS_SHADING);
}

// Shadows are tinted by transparent occluders, and an eye inside glass is
// told by the transparency at the first sample.
TEST(MaterialReads, TheTransparencyWhereAMaterialTransmits) {
    EXPECT_EQ(compiledScene("tutorial/09_glass.json").materialReads(),
              shared::MATERIAL_READS_SHADING | shared::MATERIAL_READS_TRANSPARENCY);
}

// The normal's samples carry the bump height.
TEST(MaterialReads, TheBumpHeightWhereAProceduralBumpMapIs) {
    EXPECT_EQ(compiledScene("tutorial/13_bump_map.json").materialReads(),
              shared::MATERIAL_READS_SHADING | shared::MATERIAL_READS_BUMP);
}

TEST(MaterialReads, FollowsAnEditedTransparency) {
    scene::Scene s = scene::loadSceneFile(test::sourceDir() + "/scenes/default.json");
    ASSERT_FALSE(s.materials.empty());
    program::Program before = program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
    s.materials.back().transparency = 0.25;
    program::Program after = program::compileScene(s, {.width = 16, .height = 9, .aa = 1});
    EXPECT_EQ(before.materialReads() & shared::MATERIAL_READS_TRANSPARENCY, 0);
    EXPECT_NE(after.materialReads() & shared::MATERIAL_READS_TRANSPARENCY, 0);
}

// Each phase asks for the fields it reads and no others: the AO samples and
// a march past its first sample read no material, so a glass or bump scene
// evaluates them for their distances only.
TEST(TraceMaterialReads, FollowsThePhase) {
    shared::TraceState s = shared::traceBegin(shared::Ray{glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0)});
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_TRANSPARENCY);  // the eye inside glass?
    s.steps = 1;
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_NONE);
    s.phase = shared::PHASE_NORMAL;
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_BUMP);
    s.phase = shared::PHASE_MATERIAL;
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_SHADING);
    s.phase = shared::PHASE_AO;
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_NONE);
    s.phase = shared::PHASE_SHADOW;
    EXPECT_EQ(shared::traceMaterialReads(s), shared::MATERIAL_READS_TRANSPARENCY);
}

}  // namespace
}  // namespace sdfwb
