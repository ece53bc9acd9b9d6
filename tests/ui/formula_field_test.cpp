// Formula fields in the inspector: a draft that does not parse is refused with
// its column and leaves the scene alone; a valid one is applied as one undo
// step; the inspector draws a formula node without editing it. In the Add
// menu, a formula becomes a new node only when it is valid.

#include <gtest/gtest.h>

#include <imgui.h>

#include "support/headless_imgui.h"
#include "ui/formula_field.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

struct FormulaScene {
    Editor editor;
    NodePath path{0};
    const scene::FieldSpec& field;

    explicit FormulaScene(scene::NodeKind kind)
        : editor(withNode(kind)), field(scene::kindSpec(kind).fields[scene::fieldIndex(scene::kindSpec(kind), "formula")]) {}
    static scene::Scene withNode(scene::NodeKind kind) {
        scene::Scene s;
        s.root.children.push_back(scene::Node::make(kind));
        return s;
    }
    const std::string& formula() const { return findNode(editor.scene().root, path)->text("formula"); }
};

TEST(FormulaField, InvalidDraftIsReportedWithItsColumnAndNotApplied) {
    FormulaScene s(scene::NodeKind::Implicit);
    std::string before = s.formula();
    auto revision = s.editor.revision();
    std::string reason = tryFormulaText(s.editor, s.path, s.field, "x^2 + y^2 +", "k");
    EXPECT_NE(reason.find("column"), std::string::npos) << reason;
    EXPECT_EQ(s.formula(), before);
    EXPECT_EQ(s.editor.revision(), revision);
    EXPECT_FALSE(s.editor.canUndo());
}

TEST(FormulaField, ValidDraftsAreAppliedAsOneUndoStep) {
    FormulaScene s(scene::NodeKind::Sdf);
    std::string before = s.formula();
    EXPECT_EQ(tryFormulaText(s.editor, s.path, s.field, "length(p) - 0", "k"), "");
    EXPECT_NE(tryFormulaText(s.editor, s.path, s.field, "length(p) - ", "k"), "");
    EXPECT_EQ(tryFormulaText(s.editor, s.path, s.field, "length(p) - 0.5", "k"), "");
    s.editor.endMerge();
    EXPECT_EQ(s.formula(), "length(p) - 0.5");
    ASSERT_TRUE(s.editor.undo());
    EXPECT_EQ(s.formula(), before);
    EXPECT_FALSE(s.editor.canUndo());
}

TEST(FormulaField, PolynomialFieldRejectsWhatIsNotAPolynomial) {
    FormulaScene s(scene::NodeKind::Polynomial);
    EXPECT_NE(tryFormulaText(s.editor, s.path, s.field, "sin(x) - y", "k"), "");
    EXPECT_EQ(tryFormulaText(s.editor, s.path, s.field, "x*y - z", "k"), "");
    EXPECT_EQ(s.formula(), "x*y - z");
}

TEST(AddFormula, ValidFormulaBecomesANewNodeInOneUndoStep) {
    scene::Scene start;
    Editor editor(start);
    const scene::KindSpec& implicit = scene::kindSpec(scene::NodeKind::Implicit);
    ASSERT_EQ(addFormulaNode(editor, implicit, "x^4 + y^4 + z^4 - 1"), Problems{});
    // New nodes are placed where the view looks: inside a translate, the node itself selected.
    ASSERT_EQ(editor.scene().root.children.size(), 1u);
    const scene::Node& placed = editor.scene().root.children[0];
    EXPECT_EQ(placed.kind, scene::NodeKind::Translate);
    ASSERT_EQ(placed.children.size(), 1u);
    const scene::Node& node = placed.children[0];
    EXPECT_EQ(node.kind, scene::NodeKind::Implicit);
    EXPECT_EQ(node.text("formula"), "x^4 + y^4 + z^4 - 1");
    EXPECT_EQ(editor.selection(), (NodePath{0, 0}));
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(editor.scene().root.children.empty());
}

TEST(AddFormula, InvalidFormulaIsRefusedWithItsColumn) {
    scene::Scene start;
    Editor editor(start);
    auto revision = editor.revision();
    Problems sdf = addFormulaNode(editor, scene::kindSpec(scene::NodeKind::Sdf), "length(p) - ");
    ASSERT_EQ(sdf.size(), 1u);
    EXPECT_EQ(sdf[0].find("column 13"), 0u) << sdf[0];
    Problems polynomial = addFormulaNode(editor, scene::kindSpec(scene::NodeKind::Polynomial), "sqrt(x) - y");
    ASSERT_EQ(polynomial.size(), 1u);
    EXPECT_NE(polynomial[0].find("column 1"), std::string::npos) << polynomial[0];
    EXPECT_FALSE(addFormulaNode(editor, scene::kindSpec(scene::NodeKind::Sphere), "x").empty());
    EXPECT_EQ(editor.revision(), revision);
    EXPECT_TRUE(editor.scene().root.children.empty());
}

TEST(AddFormula, GoesWhereAddPutsItsKind) {
    scene::Scene start;
    start.root.children.push_back(scene::Node::make(scene::NodeKind::Union));
    start.root.children[0].children.push_back(scene::Node::make(scene::NodeKind::Sphere));
    Editor editor(start);
    editor.select(NodePath{0, 0});
    ASSERT_EQ(addFormulaNode(editor, scene::kindSpec(scene::NodeKind::Sdf), "length(p) - 0.5"), Problems{});
    // a sphere takes no child: the new node goes next to it in the union
    ASSERT_EQ(editor.scene().root.children[0].children.size(), 2u);
    EXPECT_EQ(editor.scene().root.children[0].children[1].kind, scene::NodeKind::Sdf);
    EXPECT_EQ(editor.selection(), (NodePath{0, 1}));
}

TEST(FormulaField, InspectorDrawsFormulaNodesWithoutEditing) {
    test::HeadlessImGui imgui;
    for (scene::NodeKind kind : {scene::NodeKind::Sdf, scene::NodeKind::Implicit, scene::NodeKind::Polynomial}) {
        FormulaScene s(kind);
        s.editor.select(s.path);
        UiState ui;
        auto revision = s.editor.revision();
        for (int frame = 0; frame < 2; ++frame) {
            ImGui::NewFrame();
            ImGui::Begin("inspector");
            drawInspector(s.editor, ui);
            ImGui::End();
            ImGui::Render();
        }
        EXPECT_EQ(s.editor.revision(), revision);
        EXPECT_TRUE(ui.messages.empty());
    }
}

}  // namespace
}  // namespace sdfwb::ui
