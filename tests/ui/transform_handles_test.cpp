// Move, rotate and scale handles (issue 13, item 6): a drag edits the
// selection's transform (wrapping the node when it has none), follows the
// mouse, snaps with Ctrl, and is one undo step.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "program/rotation.h"
#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "support/still_script_host.h"
#include "ui/script.h"
#include "ui/transform_handles.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

using scene::NodeKind;

constexpr int kWidth = 480, kHeight = 270;

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

// Presses the handle of `axis`, moves `pixels` along its grip direction in a
// few steps, releases.
Problems dragHandle(Editor& editor, HandleMode mode, int axis, double pixels, bool snap = false) {
    std::optional<HandleLayout> layout = handleLayout(editor.scene(), *editor.selection(), mode, kWidth, kHeight);
    EXPECT_TRUE(layout);
    std::optional<HandleGrip> grip = handleGrip(*layout, mode, axis);
    EXPECT_TRUE(grip);
    HandleDrag drag;
    EXPECT_TRUE(drag.begin(editor, mode, kWidth, kHeight, grip->point));
    EXPECT_EQ(drag.axis(), axis);
    Problems problems;
    for (int i = 1; i <= 5; ++i) {
        Problems step = drag.update(editor, grip->point + (pixels * i / 5) * grip->direction, snap);
        problems.insert(problems.end(), step.begin(), step.end());
    }
    drag.end(editor);
    return problems;
}

TEST(Rotation, AnglesComeBackFromTheMatrix) {
    for (glm::dvec3 angles : {glm::dvec3(10, -20, 30), glm::dvec3(170, 80, -120), glm::dvec3(0, 0, 0), glm::dvec3(-45, 0, 90)}) {
        glm::dmat3 r = program::rotationFromAngles(angles);
        glm::dmat3 back = program::rotationFromAngles(program::anglesFromRotation(r));
        for (int c = 0; c < 3; ++c) {
            for (int row = 0; row < 3; ++row) EXPECT_NEAR(back[c][row], r[c][row], 1e-12);
        }
    }
    for (glm::dvec3 angles : {glm::dvec3(30, 90, 10), glm::dvec3(30, -90, 10)}) {  // gimbal lock
        glm::dmat3 locked = program::rotationFromAngles(angles);
        glm::dmat3 back = program::rotationFromAngles(program::anglesFromRotation(locked));
        for (int c = 0; c < 3; ++c) {
            for (int row = 0; row < 3; ++row) EXPECT_NEAR(back[c][row], locked[c][row], 1e-9);
        }
        EXPECT_NEAR(glm::length(program::anglesFromRotation(locked, angles) - angles), 0, 1e-6);
    }
    // the solution nearest the angles a node had: a turn past 90 or 180 goes on
    EXPECT_NEAR(glm::length(program::anglesFromRotation(program::rotationFromAngles({0, 100, 0}), {0, 95, 0}) -
                            glm::dvec3(0, 100, 0)),
                0, 1e-9);
    EXPECT_NEAR(glm::length(program::anglesFromRotation(program::rotationFromAngles({190, 0, 0}), {175, 0, 0}) -
                            glm::dvec3(190, 0, 0)),
                0, 1e-9);
}

TEST(TransformHandles, MovingFollowsTheMouseAlongTheAxisInOneUndoStep) {
    Editor editor(defaultScene());
    editor.select(NodePath{0, 0});  // the ball, inside its translate
    const HandleLayout before = *handleLayout(editor.scene(), {0, 0}, HandleMode::Move, kWidth, kHeight);
    EXPECT_NEAR(glm::length(before.pivotWorld - glm::dvec3(-0.9, 0.8, 0)), 0, 1e-12);
    HandleGrip grip = *handleGrip(before, HandleMode::Move, 0);
    ASSERT_TRUE(dragHandle(editor, HandleMode::Move, 0, 60).empty());

    const scene::Node& translate = editor.scene().root.children[0];
    EXPECT_EQ(translate.kind, NodeKind::Translate);  // its own translate edited, no new wrapper
    glm::dvec3 offset = translate.vec3("offset");
    EXPECT_GT(offset.x, -0.9 + 0.3);
    EXPECT_EQ(offset.y, 0.8);
    EXPECT_EQ(offset.z, 0.0);
    // the point of the axis under the press is under the release: it moved by
    // what the rays of the two mouse points meet the axis line (y = 0.8, z = 0) apart
    auto onAxis = [&](glm::dvec2 mouse) {
        ViewRay ray = viewRay(defaultScene(), kWidth, kHeight, mouse);
        return ray.origin.x + ray.direction.x * (0.0 - ray.origin.z) / ray.direction.z;
    };
    EXPECT_NEAR(offset.x - -0.9, onAxis(grip.point + 60.0 * grip.direction) - onAxis(grip.point), 1e-6);
    EXPECT_EQ(editor.selection(), (NodePath{0, 0}));

    EXPECT_EQ(editor.undoLabel(), "Move");
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene().root, defaultScene().root);
    EXPECT_FALSE(editor.canUndo());
}

TEST(TransformHandles, SnappingMovesInWholeSteps) {
    Editor editor(defaultScene());
    editor.select(NodePath{0, 0});
    ASSERT_TRUE(dragHandle(editor, HandleMode::Move, 1, 37, true).empty());
    double moved = editor.scene().root.children[0].vec3("offset").y - 0.8;
    EXPECT_GT(moved, 0.05);
    EXPECT_NEAR(moved / kMoveSnap, std::round(moved / kMoveSnap), 1e-9);
}

TEST(TransformHandles, ANodeWithoutTransformIsWrappedAndStaysSelected) {
    scene::Scene scene = defaultScene();
    scene.root.children.push_back(scene::Node::make(NodeKind::Torus));
    Editor editor(scene);
    editor.select(NodePath{2});
    ASSERT_TRUE(dragHandle(editor, HandleMode::Move, 2, -40).empty());
    const scene::Node& wrapper = editor.scene().root.children[2];
    ASSERT_EQ(wrapper.kind, NodeKind::Translate);
    EXPECT_NE(wrapper.vec3("offset").z, 0.0);
    EXPECT_EQ(wrapper.children[0].kind, NodeKind::Torus);
    EXPECT_EQ(editor.selection(), (NodePath{2, 0}));
    ASSERT_TRUE(editor.undo());  // the wrap and the move are one step
    EXPECT_EQ(editor.scene().root, scene.root);
}

TEST(TransformHandles, RotatingEditsTheRotateInTheChainAboutTheNodesPlace) {
    Editor editor(defaultScene());
    editor.select(NodePath{1, 0, 0});  // the crate, in translate(rotate(box))
    HandleLayout layout = *handleLayout(editor.scene(), {1, 0, 0}, HandleMode::Rotate, kWidth, kHeight);
    EXPECT_NEAR(glm::length(layout.pivotWorld - glm::dvec3(1.1, 0.6, 0.2)), 0, 1e-12);
    ASSERT_TRUE(dragHandle(editor, HandleMode::Rotate, 1, 30, true).empty());
    const scene::Node& rotate = editor.scene().root.children[1].children[0];
    ASSERT_EQ(rotate.kind, NodeKind::Rotate);
    glm::dvec3 angles = rotate.vec3("angles");
    EXPECT_NEAR(angles.x, 0, 1e-9);
    EXPECT_NEAR(angles.z, 0, 1e-9);
    EXPECT_GT(angles.y, 25 + 1);  // a positive turn about +y, in whole snap steps
    EXPECT_NEAR((angles.y - 25) / kRotateSnap, std::round((angles.y - 25) / kRotateSnap), 1e-9);
    EXPECT_EQ(editor.selection(), (NodePath{1, 0, 0}));
}

TEST(TransformHandles, ScalingWrapsInsideTheTranslateAndFollowsTheDistanceFromThePivot) {
    Editor editor(defaultScene());
    editor.select(NodePath{0, 0});
    HandleLayout layout = *handleLayout(editor.scene(), {0, 0}, HandleMode::Scale, kWidth, kHeight);
    HandleGrip grip = *handleGrip(layout, HandleMode::Scale, 0);
    double reach = glm::length(grip.point - layout.pivot);
    ASSERT_TRUE(dragHandle(editor, HandleMode::Scale, 0, reach).empty());  // twice as far from the pivot
    const scene::Node& translate = editor.scene().root.children[0];
    ASSERT_EQ(translate.children[0].kind, NodeKind::Scale);
    EXPECT_NEAR(translate.children[0].real("factor"), 2.0, 1e-9);
    EXPECT_EQ(translate.vec3("offset"), glm::dvec3(-0.9, 0.8, 0));  // it grows where it stands
    EXPECT_EQ(editor.selection(), (NodePath{0, 0, 0}));
    EXPECT_EQ(editor.undoLabel(), "Scale");
}

TEST(TransformHandles, APressAwayFromTheHandlesStartsNoDrag) {
    Editor editor(defaultScene());
    HandleDrag drag;
    EXPECT_FALSE(drag.begin(editor, HandleMode::Move, kWidth, kHeight, glm::dvec2(240, 135)));  // nothing selected
    editor.select(NodePath{0, 0});
    EXPECT_FALSE(drag.begin(editor, HandleMode::Move, kWidth, kHeight, glm::dvec2(2, 2)));
    EXPECT_FALSE(drag.active());
    // a press and release on a handle without moving changes nothing
    HandleLayout layout = *handleLayout(editor.scene(), {0, 0}, HandleMode::Move, kWidth, kHeight);
    ASSERT_TRUE(drag.begin(editor, HandleMode::Move, kWidth, kHeight, handleGrip(layout, HandleMode::Move, 0)->point));
    EXPECT_TRUE(drag.update(editor, handleGrip(layout, HandleMode::Move, 0)->point, false).empty());
    drag.end(editor);
    EXPECT_FALSE(editor.canUndo());
}


TEST(TransformHandles, ScriptsDragTheHandles) {
    Editor editor(defaultScene());
    UiState ui;
    StillScriptHost host;
    host.size = {kWidth, kHeight};
    ScriptRunner runner(parseScript("select root.children[1].children[0].children[0]\nhandles rotate\ndrag z -50 snap\n"
                                    "handles scale\ndrag x 20\n",
                                    "t.txt"),
                        "t.txt");
    ScriptStatus status = ScriptStatus::Running;
    for (int i = 0; i < 10 && status == ScriptStatus::Running; ++i) status = runner.step(editor, ui, host);
    ASSERT_EQ(status, ScriptStatus::Finished) << runner.error();
    const scene::Node& rotate = editor.scene().root.children[1].children[0];
    EXPECT_NE(rotate.vec3("angles").z, 0.0);
    ASSERT_EQ(rotate.children[0].kind, NodeKind::Scale);
    EXPECT_GT(rotate.children[0].real("factor"), 1.0);
    EXPECT_EQ(editor.undoLabel(), "Scale");
    editor.undo();
    EXPECT_EQ(editor.undoLabel(), "Rotate");

    ScriptRunner bad(parseScript("drag w 3\n", "b.txt"), "b.txt");
    EXPECT_EQ(bad.step(editor, ui, host), ScriptStatus::Failed);
    EXPECT_EQ(bad.error(), "b.txt:1: drag: the axis must be x, y or z (got w)");
}

}  // namespace
}  // namespace sdfwb::ui
