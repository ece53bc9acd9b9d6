// The GL backend's distance-only evaluations (docs/rendering.md, "Distances
// only where no material is read"): where only the material phase reads
// materials, the driver's loop runs every other evaluation on mapDistance()
// and the material phase's on map(), apart; the images are those of
// materials carried through every evaluation, bit for bit.

#include <gtest/gtest.h>

#include "gl/gl_renderer.h"
#include "gl/program_size.h"
#include "gl/shader_generator.h"
#include "gl_test_support.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/large_scenes.h"
#include "support/scene_files.h"

namespace sdfwb {
namespace {

program::Program compiledFile(const std::string& relative) {
    return program::compileScene(scene::loadSceneFile(test::SceneFile{relative}.path()),
                                 {.width = 64, .height = 36, .aa = 1});
}

TEST(MaterialApart, OnlyWhereNoOtherEvaluationReadsAMaterial) {
    EXPECT_TRUE(gl::materialSampledApart(compiledFile("default.json")));
    // image bump maps are differentiated in the material phase
    EXPECT_TRUE(gl::materialSampledApart(compiledFile("tutorial/14_image_textures.json")));
    EXPECT_FALSE(gl::materialSampledApart(compiledFile("tutorial/08_mirrors.json")));   // a ray tree
    EXPECT_FALSE(gl::materialSampledApart(compiledFile("tutorial/09_glass.json")));     // shadows read transparency
    EXPECT_FALSE(gl::materialSampledApart(compiledFile("tutorial/13_bump_map.json")));  // normals read the height
    EXPECT_FALSE(gl::materialSampledApart(compiledFile("showcase/courtyard.json")));    // a noise bump map too
    program::Program off = compiledFile("default.json");
    off.distanceOnlyEvaluation = false;
    EXPECT_FALSE(gl::materialSampledApart(off));
}

TEST(MaterialApart, ATransparencyTurningOnChangesTheStructure) {
    scene::Scene s = scene::loadSceneFile(test::SceneFile{"default.json"}.path());
    program::Program opaque = program::compileScene(s);
    std::string shader = gl::generateFragmentShader(opaque);
    EXPECT_NE(shader.find("Sample mapDistance(vec3 p) {\n"), std::string::npos);  // a distance-only copy
    ASSERT_FALSE(s.materials.empty());
    s.materials[0].transparency = 0.5;
    program::Program glass = program::compileScene(s);
    EXPECT_NE(glass.structureKey(), opaque.structureKey());
    EXPECT_NE(gl::generateFragmentShader(glass).find("Sample mapDistance(vec3 p) { return map(p); }"),
              std::string::npos);
}

class MaterialApartOnGl : public test::GlTest {
protected:
    void expectSameImage(program::Program p, const std::string& name) {
        ASSERT_TRUE(gl::materialSampledApart(p)) << name;
        gl::GlRenderer apart(gl());
        image::Frame a = apart.render(p).frame;
        p.distanceOnlyEvaluation = false;
        gl::GlRenderer everywhere(gl());
        image::Frame b = everywhere.render(p).frame;
        EXPECT_EQ(a.color.rgb, b.color.rgb) << name;
        EXPECT_EQ(a.depth, b.depth) << name;
        EXPECT_EQ(a.evaluations, b.evaluations) << name;  // the same evaluations, in either loop
    }
};

TEST_F(MaterialApartOnGl, RendersAsWithMaterialsAtEveryEvaluation) {
    expectSameImage(compiledFile("default.json"), "default");
    expectSameImage(compiledFile("tutorial/14_image_textures.json"), "image textures");  // five material samples a hit
    expectSameImage(compiledFile("showcase/chess.json"), "chess");
    expectSameImage(program::compileScene(test::moleculeScene("molecule_100"), {.width = 64, .height = 36, .aa = 1}),
                    "molecule 100");  // the fold loop
}

}  // namespace
}  // namespace sdfwb
