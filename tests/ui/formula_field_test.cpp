// Formula fields in the inspector: a draft that does not parse is refused with
// its column and leaves the scene alone; a valid one is applied as one undo
// step; the inspector draws a formula node without editing it.

#include <gtest/gtest.h>

#include <imgui.h>

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

TEST(FormulaField, InspectorDrawsFormulaNodesWithoutEditing) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 800);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
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
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace sdfwb::ui
