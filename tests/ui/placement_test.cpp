// Placement of new and duplicated nodes (issue 13, item 6): where the view
// looks, on the surface under the view centre, clear of other objects; a
// duplicate beside its original; one undo step each.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "cpu/pick.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/free_space.h"
#include "ui/node_transform.h"
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

// Whether the ray from the eye towards the node's centre meets the node first
// (traced through the field, a sphere trace of the test's own).
bool seenFromTheEye(const scene::Scene& scene, const NodePath& node) {
    program::Program program = program::compileScene(scene, {2, 2, 1});
    glm::dvec3 eye = scene::cameraFrame(scene.camera).eye;
    glm::dvec3 direction = glm::normalize(centreOf(worldBounds(scene.root, node)) - eye);
    double t = 0;
    for (int step = 0; step < 512; ++step) {
        double d = cpu::fieldDistance(scene, program, eye + t * direction);
        if (d < 1e-4) return cpu::primitiveAt(scene, program, eye + t * direction) == node;
        t += d;
    }
    return false;
}

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
    // the spot under the view centre is not free (the ball is in the way):
    // it rests on the floor beside it, and the user sees it
    EXPECT_NEAR(worldBounds(editor.scene().root, sphere).min.y, 0.0, 1e-9);
    EXPECT_TRUE(seenFromTheEye(editor.scene(), sphere));
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

// ---- every primitive kind, on several project scenes (issue 13, item 6) ----

scene::Scene projectScene(const std::string& name) {
    return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/" + name);
}

// The kinds Add places: primitives with bounds (a plane and an sdf formula
// are unbounded and go where Editor::add puts them).
std::vector<scene::NodeKind> placedKinds() {
    std::vector<scene::NodeKind> kinds;
    for (int k = 0; k < scene::kNodeKindCount; ++k) {
        auto kind = static_cast<scene::NodeKind>(k);
        if (scene::kindSpec(kind).category != scene::NodeCategory::Primitive) continue;
        program::Bounds b = program::nodeBounds(scene::Node::make(kind));
        if (!b.empty && !b.infinite) kinds.push_back(kind);
    }
    return kinds;
}

// Samples a grid over the new node's world bounds; at every sample inside
// (or on) the new primitive the scene as it was, the ground included, must
// not be inside anything. Returns how many samples fell inside the primitive.
int samplesInsideCheckedClear(const scene::Scene& before, const Editor& editor, const NodePath& added) {
    constexpr int kGrid = 14;
    program::Program old = program::compileScene(before, {2, 2, 1});
    // the primitive alone in its own frame: the sign of its field says inside
    scene::Scene alone = editor.scene();
    alone.root = *findNode(editor.scene().root, added);
    alone.environment.ground.enabled = false;
    program::Program own = program::compileScene(alone, {2, 2, 1});
    Affine innerFromWorld = worldFromInner(editor.scene().root, parentOf(added)).inverse();
    // the node's own frame relative to its parent is the identity (a primitive)
    program::Bounds b = worldBounds(editor.scene().root, added);
    int inside = 0;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            for (int k = 0; k < kGrid; ++k) {
                glm::dvec3 f = (glm::dvec3(i, j, k) + 0.5) / double(kGrid);
                glm::dvec3 world = b.min + f * (b.max - b.min);
                if (cpu::fieldDistance(alone, own, innerFromWorld.apply(world)) > 0) continue;
                ++inside;
                EXPECT_GE(cpu::fieldDistance(before, old, world), -1e-3)
                    << scene::kindSpec(findNode(editor.scene().root, added)->kind).name << " at (" << world.x << ", "
                    << world.y << ", " << world.z << ") is inside the scene";
            }
        }
    }
    return inside;
}

class PlacementOnScene : public ::testing::TestWithParam<std::string> {};

TEST_P(PlacementOnScene, EveryPrimitiveKindLandsClearOfWhatIsThereWithinTheBudget) {
    const scene::Scene before = projectScene(GetParam());
    for (scene::NodeKind kind : placedKinds()) {
        SCOPED_TRACE(scene::kindSpec(kind).name);
        Editor editor(before);
        ASSERT_TRUE(addPlaced(editor, kind).empty());
        const NodePath added = *editor.selection();
        ASSERT_EQ(findNode(editor.scene().root, added)->kind, kind);
        EXPECT_GT(samplesInsideCheckedClear(before, editor, added), 0);
        // the search that placed it stayed within its budget and found a free spot
        program::Bounds b = worldBounds(editor.scene().root, added);
        PlacementSearch search = searchPlacement(before, 0.5 * (b.max - b.min));
        EXPECT_LE(search.tests, kPlacementBudget);
        EXPECT_TRUE(search.clear);
        EXPECT_LT(glm::length(search.point - 0.5 * (b.min + b.max)), 1e-9);
    }
}

// the default scene (the one the window opens), booleans on a plinth without
// ground, a crowded board, and an unbounded plane (sampled, not bounded)
INSTANTIATE_TEST_SUITE_P(ProjectScenes, PlacementOnScene,
                         ::testing::Values("default.json", "operations/booleans.json", "showcase/chess.json",
                                           "primitives/plane.json"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(info.param.rfind('/') + 1);
                             return name.substr(0, name.find('.'));
                         });

TEST(Placement, ATorusOnTheDefaultSceneGoesThroughNeitherObject) {
    Editor editor(defaultScene());
    ASSERT_TRUE(addPlaced(editor, scene::NodeKind::Torus).empty());
    const NodePath torus = *editor.selection();
    program::Bounds placed = worldBounds(editor.scene().root, torus);
    for (const NodePath& object : {NodePath{0, 0}, NodePath{1, 0, 0}}) {
        program::Bounds other = worldBounds(editor.scene().root, object);
        bool overlap = true;
        for (int axis = 0; axis < 3; ++axis) {
            overlap = overlap && other.min[axis] < placed.max[axis] - 1e-6 && placed.min[axis] < other.max[axis] - 1e-6;
        }
        EXPECT_FALSE(overlap) << formatNodePath(object);
    }
    EXPECT_GE(placed.min.y, -1e-6);  // on the floor, not in it
}

TEST(Placement, WithNoRoomAnywhereTheSearchStopsAtItsBudget) {
    // a solid around everything, the eye included: no spot is free
    scene::Scene scene = defaultScene();
    scene::Node block = scene::Node::make(scene::NodeKind::Box);
    block.set("half_extents", glm::dvec3(500.0));
    scene.root.children.push_back(block);
    FreeSpace space(scene);
    EXPECT_FALSE(space.isClear(glm::dvec3(0, 1, 0), glm::dvec3(0.5)));
    PlacementSearch search = searchPlacement(scene, glm::dvec3(1.0));
    EXPECT_FALSE(search.clear);
    EXPECT_LE(search.tests, kPlacementBudget);
    EXPECT_GT(search.tests, kPlacementRings * kPlacementDirections / 2);  // it did look
    Editor editor(scene);
    EXPECT_TRUE(addPlaced(editor, scene::NodeKind::Sphere).empty());  // still added, where it could go
}

TEST(Placement, FreeSpaceSeesTheObjectsApartNotTheirUnion) {
    const scene::Scene scene = defaultScene();
    FreeSpace space(scene);
    ASSERT_EQ(space.obstacles().size(), 2u);  // the ball and the crate, not one box around both
    EXPECT_FALSE(space.hasUnbounded());
    EXPECT_TRUE(space.isClear(glm::dvec3(0, 3, 0), glm::dvec3(0.5)));                           // above them
    EXPECT_FALSE(space.isClear(glm::dvec3(0, 0.4, 0), glm::dvec3(1.25, 0.25, 1.25)));           // through both
    EXPECT_FALSE(space.isClear(glm::dvec3(4, 0.2, 0), glm::dvec3(0.5)));                        // in the floor
    EXPECT_TRUE(space.isClear(glm::dvec3(4, 0.5, 0), glm::dvec3(0.5)));                         // resting on it
    EXPECT_DOUBLE_EQ(space.restingHeight(glm::dvec3(-0.9, 5, 0), glm::dvec3(0.5)), 1.6 + 0.5);  // on the ball's top
    EXPECT_DOUBLE_EQ(space.restingHeight(glm::dvec3(4, 5, 0), glm::dvec3(0.5)), 0.5);           // on the floor
}

}  // namespace
}  // namespace sdfwb::ui
