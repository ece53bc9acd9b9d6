// Removing a material in use reassigns its users in one undo step (issue 13,
// item 7) instead of refusing with the loader's message.

#include <gtest/gtest.h>

#include "scene/scene_json.h"
#include "support/source_tree.h"
#include "ui/material_edits.h"

namespace sdfwb::ui {
namespace {

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

TEST(MaterialEdits, RemovingAMaterialInUseReassignsItsUsers) {
    Editor editor(defaultScene());
    EXPECT_EQ(materialUsers(editor.scene(), "red"), 1);
    EXPECT_EQ(materialUsers(editor.scene(), "floor"), 1);  // the ground
    ASSERT_TRUE(removeMaterial(editor, "red", "blue").empty());
    EXPECT_EQ(editor.scene().findMaterial("red"), nullptr);
    EXPECT_EQ(findNode(editor.scene().root, {0, 0})->text("material"), "blue");
    ASSERT_TRUE(removeMaterial(editor, "floor", "").empty());
    EXPECT_EQ(editor.scene().environment.ground.material, "");
    // one undo step each
    ASSERT_TRUE(editor.undo());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.scene(), defaultScene());
}

TEST(MaterialEdits, RefusesUnknownNamesAndItselfAsReplacement) {
    Editor editor(defaultScene());
    EXPECT_EQ(removeMaterial(editor, "gold", ""), Problems{"materials: no material named \"gold\""});
    EXPECT_EQ(removeMaterial(editor, "red", "red"), Problems{"materials: \"red\" cannot replace itself"});
    EXPECT_FALSE(editor.canUndo());
}

}  // namespace
}  // namespace sdfwb::ui
