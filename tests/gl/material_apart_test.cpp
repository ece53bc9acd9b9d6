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

// The default scene without its ray tree (max_depth 0): opaque, no bump map.
scene::Scene singleRays() {
    scene::Scene s = scene::loadSceneFile(test::SceneFile{"default.json"}.path());
    s.render.maxDepth = 0;
    return s;
}

TEST(MaterialApart, OnlyWhereNoOtherEvaluationReadsAMaterial) {
    scene::Scene s = singleRays();
    EXPECT_TRUE(gl::materialSampledApart(program::compileScene(s)));
    // image bump maps are differentiated in the material phase
    EXPECT_TRUE(gl::materialSampledApart(compiledFile("tutorial/14_image_textures.json")));
    EXPECT_FALSE(gl::materialSampledApart(compiledFile("tutorial/08_mirrors.json")));  // a ray tree

    ASSERT_FALSE(s.materials.empty());
    scene::Scene glass = s;
    glass.materials[0].transparency = 0.5;  // shadows read the transparency
    EXPECT_FALSE(gl::materialSampledApart(program::compileScene(glass)));
    scene::Scene bumpy = s;
    bumpy.materials[0].bump = scene::BumpPattern::Noise;  // normals read the height
    EXPECT_FALSE(gl::materialSampledApart(program::compileScene(bumpy)));

    program::Program off = program::compileScene(s);
    off.distanceOnlyEvaluation = false;
    EXPECT_FALSE(gl::materialSampledApart(off));
}

TEST(MaterialApart, ATransparencyTurningOnChangesTheShaderNotTheGrid) {
    scene::Scene s = singleRays();
    program::Program opaque = program::compileScene(s);
    std::string shader = gl::generateFragmentShader(opaque);
    EXPECT_NE(shader.find("Sample mapDistance(vec3 p) {\n"), std::string::npos);  // a distance-only copy
    s.materials[0].transparency = 0.5;
    program::Program glass = program::compileScene(s);
    EXPECT_NE(glass.structureKey(), opaque.structureKey());
    EXPECT_EQ(glass.codeKey(), opaque.codeKey());  // what prune grids are keyed by
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
    expectSameImage(program::compileScene(singleRays(), {.width = 64, .height = 36, .aa = 1}), "default");
    expectSameImage(compiledFile("tutorial/14_image_textures.json"), "image textures");  // five material samples a hit
    expectSameImage(compiledFile("showcase/chess.json"), "chess");
    expectSameImage(program::compileScene(test::moleculeScene("molecule_100"), {.width = 64, .height = 36, .aa = 1}),
                    "molecule 100");  // the fold loop
}

}  // namespace
}  // namespace sdfwb
