// Hide and solo in the editor (issue 13): one undo step each, scripted as
// from the scene tree's toggles, and a click in the viewport passes through a
// hidden node to what is behind it.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "support/still_script_host.h"
#include "ui/script.h"
#include "ui/transform_handles.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

ScriptStatus run(Editor& editor, const std::string& text, std::string* error = nullptr) {
    UiState ui;
    StillScriptHost host;
    ScriptRunner runner(parseScript(text, "t.txt"), "t.txt");
    ScriptStatus status = ScriptStatus::Running;
    for (int i = 0; i < 20 && status == ScriptStatus::Running; ++i) status = runner.step(editor, ui, host);
    if (error) *error = runner.error();
    return status;
}

TEST(HideSolo, TogglesAreUndoSteps) {
    Editor editor(defaultScene());
    ASSERT_EQ(run(editor, "select root.children[0].children[0]\nhide on\n"), ScriptStatus::Finished);
    EXPECT_TRUE(editor.scene().root.children[0].children[0].hidden);
    EXPECT_EQ(editor.undoLabel(), "Hide");
    EXPECT_TRUE(editor.dirty());
    ASSERT_EQ(run(editor, "select root.children[1]\nsolo on\n"), ScriptStatus::Finished);
    EXPECT_TRUE(editor.scene().root.children[1].solo);
    EXPECT_EQ(editor.undoLabel(), "Solo");
    ASSERT_TRUE(editor.undo());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), defaultScene());
    std::string error;
    EXPECT_EQ(run(editor, "select none\nhide on\n", &error), ScriptStatus::Failed);
    EXPECT_EQ(error, "t.txt:2: hide: nothing is selected");
    EXPECT_EQ(run(editor, "select root\nsolo maybe\n", &error), ScriptStatus::Failed);
    EXPECT_EQ(error, "t.txt:2: solo: must be on or off (got maybe)");
}

TEST(HideSolo, AClickPassesThroughAHiddenNode) {
    Editor editor(defaultScene());
    const int w = 480, h = 270;
    glm::dvec2 ball = *projectToView(editor.scene(), glm::dvec3(-0.9, 0.8, 0), w, h);
    ASSERT_TRUE(editor.setHidden({0, 0}, true).empty());
    selectPicked(editor, pickView(editor.scene(), w, h, ball.x, ball.y));
    EXPECT_NE(editor.selection(), (NodePath{0, 0}));
    ASSERT_TRUE(editor.setHidden({0, 0}, false).empty());
    selectPicked(editor, pickView(editor.scene(), w, h, ball.x, ball.y));
    EXPECT_EQ(editor.selection(), (NodePath{0, 0}));
}

// A selected node that draws nothing (hidden, or another node soloed) has no
// outline and no handles: they stood on empty space.
TEST(HideSolo, ANodeThatDoesNotDrawHasNoOutlineOrHandles) {
    Editor editor(defaultScene());
    const int w = 480, h = 270;
    const NodePath ball{0, 0}, crate{1};
    EXPECT_TRUE(outlineRect(editor.scene(), ball, w, h));
    EXPECT_TRUE(handleLayout(editor.scene(), ball, HandleMode::Move, w, h));
    ASSERT_TRUE(editor.setSolo(crate, true).empty());
    EXPECT_FALSE(outlineRect(editor.scene(), ball, w, h));
    EXPECT_FALSE(handleLayout(editor.scene(), ball, HandleMode::Move, w, h));
    EXPECT_TRUE(outlineRect(editor.scene(), crate, w, h)) << "the soloed one keeps them";
    ASSERT_TRUE(editor.setSolo(crate, false).empty());
    ASSERT_TRUE(editor.setHidden({0}, true).empty());
    EXPECT_FALSE(outlineRect(editor.scene(), ball, w, h)) << "inside a hidden group";
    EXPECT_FALSE(handleLayout(editor.scene(), ball, HandleMode::Rotate, w, h));
}

}  // namespace
}  // namespace sdfwb::ui
