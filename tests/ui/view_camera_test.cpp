// The camera as the user moves it (issue 13, item 5): view changes are not
// undo steps and leave the document unmodified, the orbit stops above the
// ground, Frame all returns to the home angles, presets and frame-selected.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "scene/camera_frame.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/editor.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

TEST(ViewCamera, ViewChangesAreNeitherUndoStepsNorModifications) {
    Editor editor(defaultScene());
    ASSERT_TRUE(editor.setField({0, 0}, "radius", 0.7).empty());
    editor.markSaved();
    auto revision = editor.revision();
    scene::Camera moved = orbited(editor.scene().camera, editor.scene().environment, 40, 10);
    ASSERT_TRUE(editor.setView(moved).empty());
    EXPECT_GT(editor.revision(), revision);  // the viewport renders the new view
    EXPECT_FALSE(editor.dirty());
    EXPECT_EQ(editor.undoLabel(), "Set radius");
    // undo takes back the edit and keeps the view
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(findNode(editor.scene().root, {0, 0})->real("radius"), 0.8);
    EXPECT_EQ(editor.scene().camera, moved);
    ASSERT_TRUE(editor.redo());
    EXPECT_EQ(editor.scene().camera, moved);
}

TEST(ViewCamera, ARefusedViewSaysWhyAndChangesNothing) {
    Editor editor(defaultScene());
    scene::Camera bad = editor.scene().camera;
    bad.distance = -1;
    Problems problems = editor.setView(bad);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("camera.distance"), std::string::npos) << problems[0];
    EXPECT_EQ(editor.scene().camera, defaultScene().camera);
}

TEST(ViewCamera, AnUpwardDragStopsAboveTheGround) {
    scene::Scene scene = defaultScene();
    ASSERT_TRUE(scene.environment.ground.enabled);
    scene::Camera c = scene.camera;
    for (int i = 0; i < 20; ++i) {
        c = orbited(c, scene.environment, 0, -0.4 * 45);  // 45 pixels up per step
        EXPECT_GT(scene::cameraFrame(c).eye.y, scene.environment.ground.height);
        EXPECT_FALSE(eyeBelowGround(c, scene.environment));
    }
    // zooming out along a low view keeps the eye above the ground too
    for (int i = 0; i < 30; ++i) c = zoomed(c, scene.environment, -1);
    EXPECT_GT(scene::cameraFrame(c).eye.y, scene.environment.ground.height);
    // without a ground the orbit goes down to -89 degrees
    scene.environment.ground.enabled = false;
    EXPECT_EQ(orbited(c, scene.environment, 0, -500).elevation, -89);
}

TEST(ViewCamera, AnEyeUnderTheGroundIsDetected) {
    scene::Scene scene = defaultScene();
    scene.camera.elevation = -30;
    EXPECT_TRUE(eyeBelowGround(scene.camera, scene.environment));
    scene.environment.ground.enabled = false;
    EXPECT_FALSE(eyeBelowGround(scene.camera, scene.environment));
}

TEST(ViewCamera, FrameAllReturnsToTheHomeAnglesAroundTheWholeScene) {
    scene::Scene scene = defaultScene();
    scene.camera.azimuth = 170;
    scene.camera.elevation = -60;
    scene.camera.target = glm::dvec3(40, -3, 9);
    scene.camera.distance = 0.01;
    scene::Camera home = frameAllCamera(scene);
    EXPECT_EQ(home.azimuth, kHomeAzimuth);
    EXPECT_EQ(home.elevation, kHomeElevation);
    program::Bounds bounds = program::nodeBounds(scene.root);
    glm::dvec3 centre = 0.5 * (bounds.min + bounds.max);
    EXPECT_NEAR(home.target.x, centre.x, 1e-9);
    EXPECT_NEAR(home.target.y, centre.y, 1e-9);
    EXPECT_NEAR(home.target.z, centre.z, 1e-9);
    glm::dvec3 eye = scene::cameraFrame(home).eye;
    EXPECT_GT(glm::length(eye - centre), 0.5 * glm::length(bounds.max - bounds.min));
}

TEST(ViewCamera, PresetsLookAlongTheAxes) {
    scene::Camera c = defaultScene().camera;
    auto eyeOffset = [&](ViewPreset preset) {
        scene::Camera v = presetCamera(c, preset);
        return (scene::cameraFrame(v).eye - v.target) / v.distance;
    };
    EXPECT_NEAR(eyeOffset(ViewPreset::Front).z, 1, 1e-12);
    EXPECT_NEAR(eyeOffset(ViewPreset::Back).z, -1, 1e-12);
    EXPECT_NEAR(eyeOffset(ViewPreset::Right).x, 1, 1e-12);
    EXPECT_NEAR(eyeOffset(ViewPreset::Left).x, -1, 1e-12);
    EXPECT_NEAR(eyeOffset(ViewPreset::Top).y, 1, 1e-12);
    EXPECT_NEAR(eyeOffset(ViewPreset::Bottom).y, -1, 1e-12);
    EXPECT_EQ(viewPresetNamed("top"), ViewPreset::Top);
    EXPECT_EQ(viewPresetNamed("up"), std::nullopt);
}

TEST(ViewCamera, FrameSelectedAimsAtTheNodeInWorldSpace) {
    scene::Scene scene = defaultScene();
    // root.children[1] is a translate holding a rotated box: frame the box itself
    const NodePath box{1, 0, 0};
    ASSERT_EQ(findNode(scene.root, box)->kind, scene::NodeKind::Box);
    glm::dvec3 offset = findNode(scene.root, {1})->vec3("offset");
    std::optional<scene::Camera> framed = frameSelectedCamera(scene, box);
    ASSERT_TRUE(framed);
    EXPECT_NEAR(framed->target.x, offset.x, 1e-9);
    EXPECT_NEAR(framed->target.z, offset.z, 1e-9);
    EXPECT_EQ(framed->azimuth, scene.camera.azimuth);
    // a plane has no bounds to frame
    scene.root.children.push_back(scene::Node::make(scene::NodeKind::Plane));
    EXPECT_EQ(frameSelectedCamera(scene, {2}), std::nullopt);
}

}  // namespace
}  // namespace sdfwb::ui
