// Hide and solo (issue 13): a hidden node draws nothing, in the compiled
// program (both backends run it), the pick and the bounds alike; solo draws
// only the soloed subtrees; both are saved in the scene file.

#include <gtest/gtest.h>

#include "cpu/pick.h"
#include "program/bounds.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

const glm::dvec3 kBall(-0.9, 0.8, 0), kCrate(1.1, 0.6, 0.2);

double field(const scene::Scene& scene, const glm::dvec3& at) {
    return cpu::fieldDistance(scene, program::compileScene(scene, {8, 8, 1}), at);
}

scene::Scene without(scene::Scene scene, size_t child) {
    scene.root.children.erase(scene.root.children.begin() + static_cast<long>(child));
    return scene;
}

TEST(Visibility, AHiddenNodeDrawsNothingAsIfDeleted) {
    scene::Scene scene = defaultScene();
    scene.root.children[0].children[0].hidden = true;  // the ball
    for (glm::dvec3 at : {kBall, kCrate, glm::dvec3(0, 2, 1)}) {
        EXPECT_EQ(field(scene, at), field(without(defaultScene(), 0), at));
    }
    EXPECT_TRUE(program::nodeBounds(scene.root.children[0]).empty);
    // the pick names the crate's primitive by its path in the full tree
    std::vector<std::vector<int>> paths = cpu::primitivePaths(scene.root);
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_EQ(paths[0], (std::vector<int>{1, 0, 0}));
    program::Program program = program::compileScene(scene, {8, 8, 1});
    EXPECT_EQ(cpu::primitiveAt(scene, program, kCrate), (std::vector<int>{1, 0, 0}));
    EXPECT_NE(cpu::primitiveAt(scene, program, kBall), (std::vector<int>{0, 0}));
}

TEST(Visibility, SoloDrawsOnlyTheSoloedSubtrees) {
    scene::Scene scene = defaultScene();
    scene.root.children[1].children[0].solo = true;  // the crate's rotate
    for (glm::dvec3 at : {kBall, kCrate}) EXPECT_EQ(field(scene, at), field(without(defaultScene(), 0), at));
    scene.root.children[0].children[0].solo = true;  // and the ball
    for (glm::dvec3 at : {kBall, kCrate}) EXPECT_EQ(field(scene, at), field(defaultScene(), at));
    scene.root.children[0].children[0].hidden = true;  // hidden wins over solo
    EXPECT_EQ(field(scene, kBall), field(without(defaultScene(), 0), kBall));
}

TEST(Visibility, IsSavedAndCheckedInTheSceneFile) {
    scene::Scene scene = defaultScene();
    scene.root.children[0].hidden = true;
    scene.root.children[1].solo = true;
    scene::Scene back = scene::sceneFromJson(scene::sceneToJson(scene));
    EXPECT_EQ(back, scene);
    nlohmann::ordered_json json = scene::sceneToJson(defaultScene());
    EXPECT_FALSE(json["root"]["children"][0].contains("hidden"));  // only written when set
    json["root"]["children"][0]["hidden"] = 1;
    try {
        scene::sceneFromJson(json);
        FAIL() << "accepted a number for hidden";
    } catch (const scene::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("root.children[0].hidden: must be true or false"), std::string::npos);
    }
}

}  // namespace
}  // namespace sdfwb
