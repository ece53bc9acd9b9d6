// The Problems window (View > Problems, or a click on the status bar): the
// open errors, newest first; a click on one goes to its cause.

#include <imgui.h>

#include "ui/long_text.h"
#include "ui/panels.h"
#include "ui/problems.h"

namespace sdfwb::ui {

void drawProblemsWindow(Editor& editor, UiState& ui) {
    if (!ui.showProblems) return;
    ImGui::SetNextWindowSize(ImVec2(620, 300), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Problems", &ui.showProblems)) {
        std::vector<const Message*> open = openErrors(ui);
        if (open.empty()) {
            ImGui::TextDisabled("No problems. Errors appear here until what caused them is fixed.");
        } else {
            ImGui::Text("%zu open, newest first. Click one to go to its cause.", open.size());
            ImGui::SameLine();
            if (ImGui::SmallButton("Clear all")) {
                for (Message& m : ui.messages) m.resolved = m.resolved || m.level == Message::Level::Error;
            }
        }
        ImGui::Separator();
        ImGui::BeginChild("list");
        const float width = ImGui::GetContentRegionAvail().x;
        for (size_t i = 0; i < open.size(); ++i) {
            ImGui::PushID(static_cast<int>(i));
            std::optional<ProblemCause> cause = problemCause(open[i]->text);
            std::string text = shortened(open[i]->text, 400);
            ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 130, 115, 255));
            if (cause) {
                if (ImGui::Selectable("##go", false, 0, ImVec2(width, 0))) goToCause(editor, ui, *cause);
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("Go to %s", shortened(cause->jsonPath, 200).c_str());
                ImGui::SameLine(0, 0);
                ImGui::SetCursorPosX(ImGui::GetStyle().ItemSpacing.x);
            }
            oneLineText(text, width - 8);
            ImGui::PopStyleColor();
            ImGui::PopID();
        }
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace sdfwb::ui
