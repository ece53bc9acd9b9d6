#include "ui/polynomial_panel.h"

#include <algorithm>
#include <exception>
#include <span>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/long_text.h"
#include "ui/panel_widgets.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

void orderCombo(algebra::EliminationOrder& order) {
    std::span<const algebra::EliminationOrderName> orders = algebra::eliminationOrders();
    auto current = std::find_if(orders.begin(), orders.end(), [&](const auto& entry) { return entry.order == order; });
    ImGui::SetNextItemWidth(200);
    if (ImGui::BeginCombo("monomial order", std::string(current->name).c_str())) {
        for (const algebra::EliminationOrderName& entry : orders) {
            if (ImGui::Selectable(std::string(entry.name).c_str(), entry.order == order)) order = entry.order;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(entry.description).c_str());
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(current->description).c_str());
}

void rangeWidgets(PolynomialPanelState& state) {
    ImGui::Checkbox("bounds from the parameter ranges", &state.boundsFromRanges);
    // the ranges belong to the last equations that could run
    if (!state.problem.empty()) return;
    ImGui::BeginDisabled(!state.boundsFromRanges);
    for (ParameterRange& range : state.ranges) {
        ImGui::SetNextItemWidth(200);
        double bounds[2] = {range.min, range.max};
        std::string label = range.name + " from, to";
        if (ImGui::InputScalarN(label.c_str(), ImGuiDataType_Double, bounds, 2, nullptr, nullptr, "%.4g")) {
            range.min = bounds[0];
            range.max = bounds[1];
        }
    }
    ImGui::EndDisabled();
}

void requestWidgets(PolynomialPanelState& state) {
    PolynomialRequest& r = state.request;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("parametric equations, e.g. x = u*v; y = v; z = u^2 (sin and cos of rational multiples "
                       "of parameters are converted exactly)");
    ImGui::PopStyleColor();
    ImGui::InputTextMultiline("##equations", &r.equations, ImVec2(-1, ImGui::GetTextLineHeight() * 4 + 8));
    checkParameters(state);
    if (parametersCurrent(state)) {
        problemText(state.problem);
    } else {
        ImGui::TextDisabled("reading the equations...");
    }
    orderCombo(r.order);
    int trig = r.trig == expr::TrigStrategy::CosSinRelation ? 0 : 1;
    ImGui::RadioButton("cos-sin variables", &trig, 0);
    ImGui::SameLine();
    ImGui::RadioButton("half-angle", &trig, 1);
    r.trig = trig == 0 ? expr::TrigStrategy::CosSinRelation : expr::TrigStrategy::HalfAngle;
    rangeWidgets(state);
    ImGui::SetNextItemWidth(200);
    ImGui::InputDouble("time limit (s)", &r.timeLimitSeconds, 0, 0, "%.0f");
    if (r.timeLimitSeconds < 0.1) r.timeLimitSeconds = 0.1;
}

void outcomeWidgets(Editor& editor, UiState& ui, PolynomialPanelState& state, const PolynomialOutcome& outcome) {
    ImGui::Separator();
    if (!outcome.ok) {
        problemText(outcome.message);
        return;
    }
    ImGui::TextUnformatted(outcome.message.c_str());
    if (!resultIsCurrent(state)) {
        // the equations or their reading changed since Run: say whose result this is
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(240, 190, 90, 255));
        wrappedText("outdated: the result of " + shortened(state.ran.equations, 80) +
                    " as run; Run again for the equations above");
        ImGui::PopStyleColor();
    }
    std::string equations;
    for (const std::string& g : outcome.generators) equations += (equations.empty() ? "" : "\n") + g + " = 0";
    longTextBox("result", equations, ImGui::GetTextLineHeight() * 8, state.resultText);
    ImGui::BeginDisabled(!outcome.isSurface());
    if (ImGui::Button("Add to scene")) addPolynomialNode(editor, ui, outcome, state.sheetThickness);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::InputDouble("sheet thickness", &state.sheetThickness, 0, 0, "%.3g");
    state.sheetThickness = std::max(state.sheetThickness, 0.0);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("0: the solid F <= 0 in the box. An open surface (Moebius strip, Enneper) shows\n"
                          "better as a sheet of this thickness around F = 0, e.g. 0.02.");
    }
    ImGui::EndDisabled();
}

}  // namespace

void checkParameters(PolynomialPanelState& state) {
    if (state.request.equations != state.readEquations) state.check.request(state.request.equations, state.ranges);
    if (std::optional<ParameterCheck::Result> read = state.check.take()) {
        state.readEquations = std::move(read->equations);
        state.problem = std::move(read->problem);
        if (state.problem.empty()) state.ranges = std::move(read->ranges);
    }
}

void readParameters(PolynomialPanelState& state) {
    checkParameters(state);
    state.check.wait();
    checkParameters(state);
}

bool parametersCurrent(const PolynomialPanelState& state) { return state.readEquations == state.request.equations; }

bool resultIsCurrent(const PolynomialPanelState& state) {
    return state.ran.equations == state.request.equations && state.ran.trig == state.request.trig &&
           state.ran.order == state.request.order;
}

void runPolynomial(PolynomialPanelState& state) {
    PolynomialRequest request = state.request;
    request.parameterRanges = state.boundsFromRanges ? state.ranges : std::vector<ParameterRange>{};
    state.ran = request;
    state.job.start(std::move(request));
}

Problems addPolynomialNode(Editor& editor, UiState& ui, const PolynomialOutcome& outcome, double sheetThickness) {
    Problems problems = editor.insert({}, -1, polynomialNode(outcome, sheetThickness));
    reportProblems(ui, problems);
    if (problems.empty()) ui.info("added a polynomial node of degree " + std::to_string(outcome.degree));
    return problems;
}

void drawPolynomialPanel(Editor& editor, UiState& ui, PolynomialPanelState& state, ImVec2 areaMin, ImVec2 areaMax) {
    if (!state.open) return;
    // first shown in the viewport's lower left, clear of the statistics
    // overlay and of the status bar below (it ran under it, hiding Add to scene)
    constexpr float kMargin = 16;
    ImGui::SetNextWindowPos(ImVec2(areaMin.x + kMargin, areaMax.y - kMargin), ImGuiCond_FirstUseEver, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(520, std::min(420.0f, areaMax.y - areaMin.y - 2 * kMargin)),
                             ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Polynomial", &state.open)) {
        bool running = state.job.running();
        ImGui::BeginDisabled(running);
        requestWidgets(state);
        ImGui::EndDisabled();
        if (running) {
            PolynomialProgress p = state.job.progress();
            if (ImGui::Button("Cancel")) state.job.cancel();
            ImGui::SameLine();
            // interpolation, lifting and verification have no basis or pairs to count
            if (p.basisSize > 0 || p.pairsLeft > 0) {
                ImGui::Text("%.1f s  basis %zu  pairs left %zu  %s", p.elapsedSeconds, p.basisSize, p.pairsLeft,
                            p.stage.c_str());
            } else {
                ImGui::Text("%.1f s  %s", p.elapsedSeconds, p.stage.c_str());
            }
        } else {
            ImGui::BeginDisabled(!state.problem.empty() || !parametersCurrent(state));
            if (ImGui::Button("Run")) runPolynomial(state);
            ImGui::EndDisabled();
            if (std::optional<PolynomialOutcome> outcome = state.job.outcome()) outcomeWidgets(editor, ui, state, *outcome);
        }
    }
    ImGui::End();
}

}  // namespace sdfwb::ui
