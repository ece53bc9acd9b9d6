// Edits of textures, bump maps and environment maps that docs/scene-format.md
// calls parameter edits keep the program's structure (Program::structureKey),
// so the GL backend keeps its shader and only the parameter buffer changes;
// turning a feature on where the scene had none adds code.

#include <gtest/gtest.h>

#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

scene::Scene tutorial(const std::string& file) {
    return scene::loadSceneFile(test::sourceDir() + "/scenes/tutorial/" + file);
}

std::uint64_t structure(const scene::Scene& s) { return program::compileScene(s).structureKey(); }

TEST(ParameterEdits, ProceduralTextures) {
    scene::Scene s = tutorial("10_procedural_textures.json");
    std::uint64_t key = structure(s);
    for (scene::Material& m : s.materials) {
        if (m.texture == scene::TexturePattern::None) continue;
        m.textureScale *= 3;
        m.textureColor = {0.2, 0.9, 0.4};
        m.texture =
            m.texture == scene::TexturePattern::Checker ? scene::TexturePattern::Noise : scene::TexturePattern::Checker;
        m.textureSpecular = !m.textureSpecular;
    }
    EXPECT_EQ(structure(s), key);
}

TEST(ParameterEdits, ProceduralBumpMaps) {
    scene::Scene s = tutorial("13_bump_map.json");
    std::uint64_t key = structure(s);
    for (scene::Material& m : s.materials) {
        if (m.bump == scene::BumpPattern::None) continue;
        m.bumpScale *= 2;
        m.bumpDepth *= 0.5;
        m.bump = m.bump == scene::BumpPattern::Noise ? scene::BumpPattern::Waves : scene::BumpPattern::Noise;
    }
    EXPECT_EQ(structure(s), key);
}

TEST(ParameterEdits, ImageTextures) {
    scene::Scene s = tutorial("14_image_textures.json");
    std::uint64_t key = structure(s);
    int textured = 0;
    for (scene::Material& m : s.materials) {
        if (m.texture != scene::TexturePattern::Image) continue;
        m.textureImage = "../textures/uv_grid.png";
        m.textureScale *= 2;
        m.textureSpecular = !m.textureSpecular;
        ++textured;
    }
    ASSERT_GT(textured, 0);
    EXPECT_EQ(structure(s), key);
}

TEST(ParameterEdits, EnvironmentMaps) {
    scene::Scene s = tutorial("11_environment_map.json");
    ASSERT_EQ(s.environment.map, scene::EnvironmentMapKind::Equirect);
    std::uint64_t key = structure(s);
    s.environment.intensity = 3;
    EXPECT_EQ(structure(s), key);
    s.environment.map = scene::EnvironmentMapKind::Sphere;
    s.environment.image = "../environments/sky_sphere.png";
    EXPECT_EQ(structure(s), key);
    s.environment.map = scene::EnvironmentMapKind::Box;
    EXPECT_EQ(structure(s), key);
    // a constant colour compiles no sampler
    s.environment.map = scene::EnvironmentMapKind::Color;
    EXPECT_NE(structure(s), key);
}

TEST(ParameterEdits, AFirstTextureAddsCode) {
    scene::Scene s = tutorial("10_procedural_textures.json");
    std::uint64_t key = structure(s);
    for (scene::Material& m : s.materials) m.texture = scene::TexturePattern::None;
    EXPECT_NE(structure(s), key);
}

}  // namespace
}  // namespace sdfwb
