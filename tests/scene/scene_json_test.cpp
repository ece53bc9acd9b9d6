#include <gtest/gtest.h>

#include "support/scene_files.h"
#include "support/scratch_folder.h"
#include "scene/scene_json.h"

namespace sdfwb::scene {
namespace {

TEST(SceneJson, EveryShippedSceneRoundTripsAndSavesByteStable) {
    auto files = test::allSceneFiles();
    ASSERT_FALSE(files.empty());
    for (const auto& file : files) {
        SCOPED_TRACE(file.relative);
        Scene loaded = loadSceneFile(file.path());
        std::string saved = serializeScene(loaded);
        Scene reloaded = parseScene(saved);
        EXPECT_EQ(loaded, reloaded);
        EXPECT_EQ(saved, serializeScene(reloaded));
    }
}

TEST(SceneJson, MinimalFileGetsDefaults) {
    Scene scene = parseScene(R"({"format": "sdf-workbench-scene", "version": 1,
                                 "root": {"kind": "sphere"}})");
    EXPECT_EQ(scene.root.kind, NodeKind::Sphere);
    EXPECT_EQ(scene.root.real("radius"), 1.0);
    EXPECT_EQ(scene.render, RenderSettings{});
    EXPECT_EQ(scene.camera, Camera{});
    ASSERT_EQ(scene.lights.size(), 1u);
}

TEST(SceneJson, SaveAndLoadFileIsEqual) {
    Scene scene;
    scene.name = "saved";
    scene.materials.push_back(Material{.name = "gold"});
    Node sphere = Node::make(NodeKind::Sphere);
    sphere.set("material", std::string("gold"));
    scene.root.children.push_back(sphere);
    sdfwb::test::ScratchFolder folder;
    saveSceneFile(scene, folder / "saved.json");
    EXPECT_EQ(loadSceneFile(folder / "saved.json"), scene);
}

TEST(SceneJson, NodesRoundTripThroughJson) {
    Node node = Node::make(NodeKind::SmoothUnion);
    node.name = "blend";
    node.children.push_back(Node::make(NodeKind::Torus));
    node.children.push_back(Node::make(NodeKind::Capsule));
    EXPECT_EQ(nodeFromJson(nodeToJson(node), "root"), node);
}

}  // namespace
}  // namespace sdfwb::scene
