#include "ui/formula_field.h"

#include <imgui.h>
#include <imgui_stdlib.h>

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
    if (reason.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
    ImGui::TextWrapped("%s", reason.c_str());
    ImGui::PopStyleColor();
}

}  // namespace sdfwb::ui
