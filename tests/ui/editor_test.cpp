// The edit layer without a window: edits, validation with the loader's
// messages, undo/redo with merged drags, selection, dirty tracking.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "scene/scene_validation.h"
#include "support/source_tree.h"
#include "ui/editor.h"

namespace sdfwb::ui {
namespace {

using scene::Node;
using scene::NodeKind;

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

const NodePath kBall = {0, 0};  // root.children[0].children[0]: the sphere "ball"

TEST(NodePathTest, FormatsAndParsesJsonPaths) {
    EXPECT_EQ(formatNodePath({}), "root");
    EXPECT_EQ(formatNodePath({1, 0}), "root.children[1].children[0]");
    EXPECT_EQ(parseNodePath("root.children[1].children[0]"), (NodePath{1, 0}));
    EXPECT_EQ(parseNodePath("root"), NodePath{});
    EXPECT_FALSE(parseNodePath("root.children[x]"));
    EXPECT_FALSE(parseNodePath("root.children[1"));
    EXPECT_FALSE(parseNodePath("children[0]"));
}

TEST(EditorTest, SetFieldAppliesAndUndoRestores) {
    Editor editor(defaultScene());
    const scene::Scene original = editor.scene();
    EXPECT_FALSE(editor.dirty());
    EXPECT_TRUE(editor.setField(kBall, "radius", 0.5).empty());
    EXPECT_EQ(findNode(editor.scene().root, kBall)->real("radius"), 0.5);
    EXPECT_TRUE(editor.dirty());
    EXPECT_EQ(editor.undoLabel(), "Set radius");
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), original);
    EXPECT_FALSE(editor.dirty());
    ASSERT_TRUE(editor.redo());
    EXPECT_EQ(findNode(editor.scene().root, kBall)->real("radius"), 0.5);
}

TEST(EditorTest, InvalidValueIsRefusedWithTheLoadersMessage) {
    Editor editor(defaultScene());
    auto revision = editor.revision();
    Problems problems = editor.setField(kBall, "radius", -1.0);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "root.children[0].children[0].radius: must be > 0 (got -1)");
    EXPECT_EQ(editor.revision(), revision);
    EXPECT_FALSE(editor.canUndo());

    problems = editor.setField(kBall, "material", std::string("gold"));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "root.children[0].children[0].material: no material named \"gold\" in materials");
}

TEST(EditorTest, DragEditsMergeIntoOneStep) {
    Editor editor(defaultScene());
    for (double r : {0.7, 0.6, 0.5}) {
        EXPECT_TRUE(editor.setField(kBall, "radius", r, "drag radius").empty());
    }
    editor.endMerge();
    EXPECT_TRUE(editor.setField(kBall, "radius", 0.4, "drag radius").empty());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(findNode(editor.scene().root, kBall)->real("radius"), 0.5);
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(findNode(editor.scene().root, kBall)->real("radius"), 0.8);
    EXPECT_FALSE(editor.canUndo());
}

TEST(EditorTest, DeleteTakesEveryWrapperItEmptiesInOneStep) {
    Editor editor(defaultScene());
    // the box sits in a rotate in a translate: all three go, one undo step
    EXPECT_TRUE(editor.remove({1, 0, 0}).empty());
    EXPECT_EQ(editor.undoLabel(), "Delete box and 2 wrappers");
    ASSERT_EQ(editor.scene().root.children.size(), 1u);
    EXPECT_TRUE(scene::validateScene(editor.scene()).empty());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), defaultScene());
    // a root wrapper left empty becomes an empty union
    scene::Scene wrapped = defaultScene();
    scene::Node root = scene::Node::make(NodeKind::Translate);
    root.children.push_back(scene::Node::make(NodeKind::Sphere));
    wrapped.root = root;
    Editor single(wrapped);
    EXPECT_TRUE(single.remove({0}).empty());
    EXPECT_EQ(single.scene().root.kind, NodeKind::Union);
    EXPECT_TRUE(single.scene().root.children.empty());
}

TEST(EditorTest, AddWrapDuplicateDeleteAndSelection) {
    Editor editor(defaultScene());
    // add into the root union (selection empty), the new node is selected
    EXPECT_TRUE(editor.add(NodeKind::Torus, std::nullopt).empty());
    EXPECT_EQ(editor.selection(), (NodePath{2}));
    EXPECT_EQ(editor.selectedNode()->kind, NodeKind::Torus);
    // adding a unary operator wraps the selection
    EXPECT_TRUE(editor.add(NodeKind::Translate, std::nullopt).empty());
    EXPECT_EQ(editor.selectedNode()->kind, NodeKind::Translate);
    EXPECT_EQ(editor.selectedNode()->children.at(0).kind, NodeKind::Torus);
    // a primitive added with a full unary node selected goes next to it
    EXPECT_TRUE(editor.add(NodeKind::Sphere, std::nullopt).empty());
    EXPECT_EQ(editor.selection(), (NodePath{3}));
    EXPECT_TRUE(editor.duplicate({3}).empty());
    EXPECT_EQ(editor.scene().root.children.size(), 5u);
    EXPECT_TRUE(editor.remove({4}).empty());
    EXPECT_EQ(editor.selection(), NodePath{});
    EXPECT_EQ(editor.scene().root.children.size(), 4u);
    // deleting the only child of a translate takes the emptied translate too
    EXPECT_TRUE(editor.remove({0, 0}).empty());
    EXPECT_EQ(editor.undoLabel(), "Delete sphere and 1 wrapper");
    EXPECT_EQ(editor.scene().root.children.size(), 3u);
    EXPECT_EQ(editor.selection(), NodePath{});
    EXPECT_FALSE(editor.remove({}).empty());
    while (editor.undo()) {
    }
    EXPECT_EQ(editor.scene(), defaultScene());
}

TEST(EditorTest, MoveReordersAndReparents) {
    Editor editor(defaultScene());
    // reorder: the second child of the root union to the front
    EXPECT_TRUE(editor.move({1}, {}, 0).empty());
    EXPECT_EQ(editor.scene().root.children[0].children[0].kind, NodeKind::Rotate);
    EXPECT_EQ(editor.selection(), NodePath{0});
    EXPECT_TRUE(editor.undo());
    // moving to the end of the same parent counts the index before the move
    EXPECT_TRUE(editor.move({0}, {}, 2).empty());
    EXPECT_EQ(editor.scene().root.children[1].children[0].name, "ball");
    EXPECT_TRUE(editor.undo());
    // reparent into a new union that comes after the source
    EXPECT_TRUE(editor.add(NodeKind::Union, std::vector<int>{}).empty());  // root.children[2]
    EXPECT_TRUE(editor.move({0}, {2}, 0).empty());
    EXPECT_EQ(editor.selection(), (NodePath{1, 0}));
    EXPECT_EQ(findNode(editor.scene().root, {1, 0, 0})->name, "ball");
    // a node cannot move into its own subtree
    EXPECT_FALSE(editor.move({1}, {1, 0}, 0).empty());
}

TEST(EditorTest, WrapAndRename) {
    Editor editor(defaultScene());
    EXPECT_TRUE(editor.wrap(kBall, NodeKind::SmoothUnion).empty());
    EXPECT_EQ(findNode(editor.scene().root, kBall)->kind, NodeKind::SmoothUnion);
    EXPECT_EQ(findNode(editor.scene().root, {0, 0, 0})->name, "ball");
    EXPECT_TRUE(editor.rename({0, 0, 0}, "orb").empty());
    EXPECT_EQ(findNode(editor.scene().root, {0, 0, 0})->name, "orb");
    EXPECT_FALSE(editor.wrap(kBall, NodeKind::Sphere).empty());
}

TEST(EditorTest, JsonPathEditsUseTheLoader) {
    Editor editor(defaultScene());
    EXPECT_TRUE(editor.setJsonValue("render.aa", 3).empty());
    EXPECT_EQ(editor.scene().render.aa, 3);
    EXPECT_TRUE(editor.setJsonValue("lights[1].softness", 4.0).empty());
    EXPECT_EQ(editor.scene().lights[1].softness, 4.0);
    Problems problems = editor.setJsonValue("render.aa", 9);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "render.aa: must be a whole number from 1 to 8 (got 9)");
    EXPECT_FALSE(editor.setJsonValue("lights[7].softness", 1.0).empty());
    EXPECT_FALSE(editor.setJsonValue("render.typo", 1).empty());
    EXPECT_FALSE(editor.setJsonValue("render..aa", 1).empty());
}

TEST(EditorTest, LightsAreLimitedToEight) {
    Editor editor(defaultScene());
    for (int i = 0; i < 6; ++i) {
        EXPECT_TRUE(editor.apply("Add light", [](scene::Scene& s) { s.lights.push_back({}); }).empty());
    }
    Problems problems = editor.apply("Add light", [](scene::Scene& s) { s.lights.push_back({}); });
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0], "lights: at most 8 lights (got 9)");
}

TEST(EditorTest, SavingClearsDirtyAndUndoAfterSaveIsDirty) {
    Editor editor(defaultScene());
    EXPECT_TRUE(editor.setField(kBall, "radius", 0.5).empty());
    editor.markSaved();
    EXPECT_FALSE(editor.dirty());
    editor.undo();
    EXPECT_TRUE(editor.dirty());
    editor.redo();
    EXPECT_FALSE(editor.dirty());
    editor.reset(scene::Scene{});
    EXPECT_FALSE(editor.dirty());
    EXPECT_FALSE(editor.canUndo());
}

}  // namespace
}  // namespace sdfwb::ui
