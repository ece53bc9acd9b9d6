// Placement of new and duplicated nodes (issue 13, item 6): where the view
// looks, on the surface under the view centre, clear of other objects; a
// duplicate beside its original; one undo step each.

#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "cpu/pick.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/placement.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

// The scene's field at a world point, without the node at `skip`.
double fieldWithout(scene::Scene scene, const NodePath& skip, const glm::dvec3& world) {
    NodePath parent = parentOf(skip);
    auto& children = findNode(scene.root, parent)->children;
    children.erase(children.begin() + skip.back());
    program::Program program = program::compileScene(scene, {2, 2, 1});
    return cpu::fieldDistance(scene, program, world);
}

glm::dvec3 centreOf(const program::Bounds& b) { return 0.5 * (b.min + b.max); }

TEST(Placement, ANewSphereRestsOnTheSurfaceUnderTheViewCentre) {
    Editor editor(defaultScene());
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Sphere).empty());
    EXPECT_EQ(editor.undoLabel(), "Add sphere");
    const NodePath sphere = *editor.selection();
    ASSERT_EQ(findNode(editor.scene().root, sphere)->kind, scene::NodeKind::Sphere);
    ASSERT_EQ(findNode(editor.scene().root, parentOf(sphere))->kind, scene::NodeKind::Translate);
    glm::dvec3 centre = centreOf(worldBounds(editor.scene().root, sphere));
    EXPECT_GT(glm::length(centre), 0.5);  // not at the origin, inside the box
    // clear of everything else, the ground included, and touching it
    double clearance = fieldWithout(editor.scene(), parentOf(sphere), centre);
    EXPECT_GE(clearance, 0.999);
    // near what it was moved off: its bounding box, of half extent 1, touches
    // it, up to sqrt(3) away along a diagonal
    EXPECT_LT(clearance, std::sqrt(3.0) + 0.01);
    // the user sees it at the view centre
    EXPECT_EQ(cpu::pickViewCentre(editor.scene()).node, sphere);
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), defaultScene());
}

TEST(Placement, WithNothingUnderTheCentreItGoesInFrontOfTheCamera) {
    scene::Scene scene = defaultScene();
    scene.camera.elevation = -20;  // looking up at the sky, the target in the open
    scene.camera.target = glm::dvec3(0, 3, 0);
    scene.environment.ground.enabled = false;
    Editor editor(scene);
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Box).empty());
    glm::dvec3 centre = centreOf(worldBounds(editor.scene().root, *editor.selection()));
    EXPECT_NEAR(glm::length(centre - scene.camera.target), 0, 1e-9);
}

TEST(Placement, ATargetInsideASolidMovesTowardsTheEye) {
    scene::Scene scene = defaultScene();
    scene.environment.ground.enabled = false;
    scene.camera.target = glm::dvec3(1.1, 0.6, 0.2);  // the crate's centre
    scene.camera.elevation = 80;                        // the centre ray passes the crate's top face first
    scene.camera.azimuth = 0;
    scene.camera.distance = 8;
    Editor editor(scene);
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Sphere).empty());
    const NodePath sphere = *editor.selection();
    glm::dvec3 centre = centreOf(worldBounds(editor.scene().root, sphere));
    EXPECT_GE(fieldWithout(editor.scene(), parentOf(sphere), centre), 0.999);
}

TEST(Placement, UnderAScaledParentTheWorldPositionIsStillTheViewCentre) {
    scene::Scene scene = defaultScene();
    scene::Node scale = scene::Node::make(scene::NodeKind::Scale);
    scale.set("factor", 2.0);
    scale.children.push_back(scene::Node::make(scene::NodeKind::Union));
    scene.root.children.push_back(scale);
    Editor editor(scene);
    editor.select(NodePath{2, 0});  // the union inside the scale
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Sphere).empty());
    const NodePath sphere = *editor.selection();
    ASSERT_EQ(sphere, (NodePath{2, 0, 0, 0}));
    glm::dvec3 centre = centreOf(worldBounds(editor.scene().root, sphere));
    // a unit sphere scaled by 2 finds room (it rises over the gap it does not fit in), in front of the eye
    EXPECT_GE(fieldWithout(editor.scene(), parentOf(sphere), centre), 1.99);
    scene::CameraFrame frame = scene::cameraFrame(editor.scene().camera);
    EXPECT_GT(glm::dot(centre - frame.eye, frame.forward), 2.0);
}

TEST(Placement, ADuplicateLandsBesideItsOriginalNotOnIt) {
    Editor editor(defaultScene());
    const NodePath ball{0, 0};
    ASSERT_TRUE(duplicatePlaced(editor, ball).empty());
    EXPECT_EQ(editor.undoLabel(), "Duplicate");
    const NodePath copy = *editor.selection();
    ASSERT_EQ(findNode(editor.scene().root, copy)->kind, scene::NodeKind::Sphere);
    program::Bounds original = worldBounds(editor.scene().root, ball), duplicate = worldBounds(editor.scene().root, copy);
    bool overlap = true;
    for (int axis = 0; axis < 3; ++axis) {
        overlap = overlap && original.min[axis] < duplicate.max[axis] && duplicate.min[axis] < original.max[axis];
    }
    EXPECT_FALSE(overlap);
    EXPECT_GE(fieldWithout(editor.scene(), parentOf(copy), centreOf(duplicate)), 0.799);  // clear of the rest
    // the ball alone in its translate was copied with the translate, which moved
    EXPECT_EQ(copy, (NodePath{1, 0}));
    EXPECT_EQ(editor.scene().root.children.size(), 3u);
    EXPECT_EQ(findNode(editor.scene().root, NodePath{1})->kind, scene::NodeKind::Translate);
    // the crate likewise, its rotate kept
    ASSERT_TRUE(duplicatePlaced(editor, NodePath{2, 0, 0}).empty());
    EXPECT_EQ(editor.selection(), (NodePath{3, 0, 0}));
    EXPECT_EQ(findNode(editor.scene().root, NodePath{3, 0})->kind, scene::NodeKind::Rotate);
    ASSERT_TRUE(editor.undo());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), defaultScene());
}

TEST(Placement, NewNodesNeverEncloseTheEye) {
    Editor editor(defaultScene());
    for (scene::NodeKind kind : {scene::NodeKind::Sphere, scene::NodeKind::Torus, scene::NodeKind::Box,
                                 scene::NodeKind::Torus, scene::NodeKind::Sphere}) {
        ASSERT_TRUE(addPlaced(editor, kind).empty());
        program::Bounds b = worldBounds(editor.scene().root, *editor.selection());
        glm::dvec3 eye = scene::cameraFrame(editor.scene().camera).eye;
        bool enclosed = true;
        for (int axis = 0; axis < 3; ++axis) enclosed = enclosed && b.min[axis] <= eye[axis] && eye[axis] <= b.max[axis];
        EXPECT_FALSE(enclosed) << "after adding " << scene::kindSpec(kind).name;
        editor.select(std::nullopt);
    }
}

TEST(Placement, UnboundedNodesAndEmptyBooleansGoWhereAddPutsThem) {
    Editor editor(defaultScene());
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Plane).empty());
    EXPECT_EQ(editor.selection(), (NodePath{2}));
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Union).empty());
    EXPECT_EQ(editor.selectedNode()->kind, scene::NodeKind::Union);
}

}  // namespace
}  // namespace sdfwb::ui
