#include "ui/formula_field.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/panel_widgets.h"
#include "ui/panels.h"
#include "ui/placement.h"

namespace sdfwb::ui {

std::string tryFormulaText(Editor& editor, const NodePath& path, const scene::FieldSpec& field,
                           const std::string& text, std::string_view mergeKey) {
    Problems problems = editor.setField(path, field.name, text, mergeKey);
    if (problems.empty()) return {};
    // checkField's words carry the column without the node path in front
    std::string reason = scene::checkField(field, text);
    if (!reason.empty()) return reason;
    std::string joined;
    for (const std::string& problem : problems) joined += (joined.empty() ? "" : "\n") + problem;
    return joined;
}

const scene::FieldSpec* formulaField(const scene::KindSpec& kind) {
    for (const scene::FieldSpec& field : kind.fields) {
        if (field.type == scene::FieldType::Formula) return &field;
    }
    return nullptr;
}

void drawFormulaField(Editor& editor, UiState& ui, const NodePath& path, const scene::FieldSpec& field,
                      const std::string& value) {
    ImGui::TextDisabled("%s", std::string(field.name).c_str());
    std::string text = value;
    std::string label = "##" + std::string(field.name);
    bool changed = ImGui::InputTextMultiline(label.c_str(), &text,
                                             ImVec2(-1, ImGui::GetTextLineHeight() * 5 + 8));
    // one undo step per node field while the box stays active
    std::string key = "formula " + formatNodePath(path) + "." + std::string(field.name);
    if (ImGui::IsItemDeactivated()) editor.endMerge();
    if (!changed) return;
    std::string reason = tryFormulaText(editor, path, field, text, key);
    // the draft's problem belongs under the box, not in the log every frame
    ui.inspectorProblems.clear();
    problemText(reason);
}

Problems addFormulaNode(Editor& editor, const scene::KindSpec& kind, const std::string& formula) {
    const scene::FieldSpec* field = formulaField(kind);
    if (!field) return {"a " + std::string(kind.name) + " node has no formula"};
    if (std::string reason = scene::checkField(*field, formula); !reason.empty()) return {reason};
    scene::Node node = scene::Node::make(kind.kind);
    node.set(field->name, formula);
    return addPlaced(editor, std::move(node));
}

void drawAddFormulaMenu(Editor& editor, UiState& ui, const scene::KindSpec& kind) {
    std::string name(kind.name);
    if (!ImGui::BeginMenu(name.c_str())) return;
    auto [draft, fresh] = ui.addFormulaDrafts.try_emplace(name);
    if (fresh) draft->second = std::get<std::string>(formulaField(kind)->defaultValue);
    ImGui::TextDisabled("%s", kind.name == "sdf" ? "signed distance of the point p (or x, y, z)"
                                                 : "F(x, y, z), zero on the surface, negative inside");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(360);
    // every kind's submenu is the same ImGui window: the label keeps their
    // text boxes (cursor, undo) apart
    std::string label = "##formula " + name;
    bool entered = ImGui::InputText(label.c_str(), &draft->second, ImGuiInputTextFlags_EnterReturnsTrue);
    std::string reason = scene::checkField(*formulaField(kind), draft->second);
    // Enter on a formula that cannot be added leaves the box in ImGui 1.86:
    // take the keyboard back, or the next keys reach the global shortcuts
    if (entered && !reason.empty()) ImGui::SetKeyboardFocusHere(-1);
    problemText(reason);
    ImGui::BeginDisabled(!reason.empty());
    bool pressed = ImGui::Button(("Add " + name).c_str());
    ImGui::EndDisabled();
    if ((pressed || entered) && reason.empty()) {
        Problems problems = addFormulaNode(editor, kind, draft->second);
        reportProblems(ui, problems);
        if (problems.empty()) ImGui::CloseCurrentPopup();
    }
    ImGui::EndMenu();
}

}  // namespace sdfwb::ui
