#include "ui/polynomial_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

const ImU32 kErrorColour = IM_COL32(255, 110, 100, 255);

void requestWidgets(PolynomialPanelState& state) {
    PolynomialRequest& r = state.request;
    ImGui::TextDisabled("parametric equations (sin/cos of rational multiples of parameters are exact)");
    ImGui::InputTextMultiline("##equations", &r.equations, ImVec2(-1, ImGui::GetTextLineHeight() * 4 + 8));
    int trig = r.trig == expr::TrigStrategy::CosSinRelation ? 0 : 1;
    ImGui::RadioButton("cos-sin variables", &trig, 0);
    ImGui::SameLine();
    ImGui::RadioButton("half-angle", &trig, 1);
    r.trig = trig == 0 ? expr::TrigStrategy::CosSinRelation : expr::TrigStrategy::HalfAngle;
    ImGui::Checkbox("bounds from parameter range", &state.useRange);
    ImGui::BeginDisabled(!state.useRange);
    ImGui::SetNextItemWidth(200);
    double range[2] = {state.rangeMin, state.rangeMax};
    if (ImGui::InputScalarN("every parameter in", ImGuiDataType_Double, range, 2, nullptr, nullptr, "%.3g")) {
        state.rangeMin = range[0];
        state.rangeMax = range[1];
    }
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(200);
    ImGui::InputDouble("time limit (s)", &r.timeLimitSeconds, 0, 0, "%.0f");
    if (r.timeLimitSeconds < 0.1) r.timeLimitSeconds = 0.1;
}

void outcomeWidgets(Editor& editor, UiState& ui, const PolynomialOutcome& outcome) {
    ImGui::Separator();
    if (!outcome.ok) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
        ImGui::TextWrapped("%s", outcome.message.c_str());
        ImGui::PopStyleColor();
        return;
    }
    ImGui::TextUnformatted(outcome.message.c_str());
    for (const std::string& g : outcome.generators) {
        std::string line = g + " = 0";
        ImGui::TextWrapped("%s", line.c_str());
    }
    ImGui::BeginDisabled(!outcome.isSurface());
    if (ImGui::Button("Add to scene")) addPolynomialNode(editor, ui, outcome);
    ImGui::EndDisabled();
}

}  // namespace

Problems addPolynomialNode(Editor& editor, UiState& ui, const PolynomialOutcome& outcome) {
    Problems problems = editor.insert({}, -1, polynomialNode(outcome));
    reportProblems(ui, problems);
    if (problems.empty()) ui.info("added a polynomial node of degree " + std::to_string(outcome.degree));
    return problems;
}

void drawPolynomialPanel(Editor& editor, UiState& ui, PolynomialPanelState& state) {
    if (!state.open) return;
    ImGui::SetNextWindowSize(ImVec2(520, 420), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Polynomial", &state.open)) {
        bool running = state.job.running();
        ImGui::BeginDisabled(running);
        requestWidgets(state);
        ImGui::EndDisabled();
        if (running) {
            PolynomialProgress p = state.job.progress();
            if (ImGui::Button("Cancel")) state.job.cancel();
            ImGui::SameLine();
            ImGui::Text("%.1f s  basis %zu  pairs left %zu  %s", p.elapsedSeconds, p.basisSize, p.pairsLeft,
                        p.stage.c_str());
        } else {
            if (ImGui::Button("Run")) {
                PolynomialRequest request = state.request;
                if (state.useRange) request.parameterRange = std::pair{state.rangeMin, state.rangeMax};
                state.job.start(std::move(request));
            }
            if (std::optional<PolynomialOutcome> outcome = state.job.outcome()) outcomeWidgets(editor, ui, *outcome);
        }
    }
    ImGui::End();
}

}  // namespace sdfwb::ui
