#include "ui/panel_widgets.h"

#include <imgui.h>
#include <imgui_internal.h>  // GetItemID: the merge key of a drag

#include "ui/long_text.h"
#include "ui/panels.h"

namespace sdfwb::ui {

namespace {
WidgetEdit finishEdit(bool changed) {
    return {changed, ImGui::IsItemDeactivatedAfterEdit()};
}
}  // namespace

WidgetEdit dragReal(const char* label, double& value, double speed, double minimum, double maximum,
                    const char* format) {
    bool changed = ImGui::DragScalar(label, ImGuiDataType_Double, &value, static_cast<float>(speed),
                                     &minimum, &maximum, format);
    return finishEdit(changed);
}

WidgetEdit dragVec3(const char* label, glm::dvec3& value, double speed, double minimum, double maximum,
                    const char* format) {
    bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, &value.x, 3, static_cast<float>(speed),
                                      &minimum, &maximum, format);
    return finishEdit(changed);
}

WidgetEdit colorEdit(const char* label, glm::dvec3& value) {
    float c[3] = {static_cast<float>(value.x), static_cast<float>(value.y), static_cast<float>(value.z)};
    bool changed = ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    if (changed) value = glm::dvec3(c[0], c[1], c[2]);
    return finishEdit(changed);
}

void commitEdit(Editor& editor, UiState& ui, const WidgetEdit& edit, const char* label,
                const std::function<void(scene::Scene&)>& change) {
    if (edit.changed) {
        std::string key = std::to_string(ImGui::GetItemID());
        Problems problems = editor.apply(label, change, key);
        ui.inspectorProblems = problems;
        reportProblems(ui, problems);
    }
    if (edit.finished) {
        editor.endMerge();
    }
}

void reportProblems(UiState& ui, const Problems& problems) {
    for (const std::string& problem : problems) {
        ui.error(problem);
    }
}

void problemText(const std::string& problem) {
    if (problem.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 110, 100, 255));
    wrappedText(problem);
    ImGui::PopStyleColor();
}

}  // namespace sdfwb::ui
