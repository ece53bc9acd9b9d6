#include "ui/quality_panel.h"

#include <cstdio>
#include <string>

#include <imgui.h>

#include "tradeoff/presets.h"
#include "ui/panel_widgets.h"
#include "ui/setting_widgets.h"

namespace sdfwb::ui {
namespace {

std::string describeEstimate(const tradeoff::SceneMeasurements* measured, const scene::RenderSettings& render) {
    if (measured == nullptr) return "no measurement of this scene (sdf-workbench tradeoff makes one)";
    std::optional<tradeoff::ErrorEstimate> e = tradeoff::estimateError(*measured, render);
    if (!e) return "these settings were not measured for this scene";
    char text[160];
    std::snprintf(text, sizeof text, "within %.2f/255 of the reference (mean), %.2fx the speed of the scene's default",
                  e->meanError, e->speedupOverDefault);
    return text;
}

}  // namespace

void drawQualityPresets(Editor& editor, UiState& ui, const tradeoff::SceneMeasurements* measured) {
    ImGui::TextDisabled("Quality presets");
    for (const tradeoff::QualityPreset& preset : tradeoff::qualityPresets()) {
        ImGui::SameLine();
        std::string label(preset.name);
        if (ImGui::SmallButton(label.c_str())) {
            scene::RenderSettings r = tradeoff::applyPreset(preset, editor.scene().render);
            commitEdit(editor, ui, {true, true}, "Quality preset", [&r](scene::Scene& s) { s.render = r; });
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%.*s", static_cast<int>(preset.why.size()), preset.why.data());
    }
    ImGui::TextWrapped("%s", describeEstimate(measured, editor.scene().render).c_str());
    // the settings the presets trade against each other (the table's Quality rows)
    scene::RenderSettings r = editor.scene().render;
    ImGui::PushItemWidth(-130);
    for (const scene::Setting<scene::RenderSettings>& row : scene::renderSettings()) {
        if (row.widget.section != scene::EditorSection::Quality) continue;
        commitEdit(
            editor, ui, settingWidget(row, r), "Edit render settings", [&r](scene::Scene& s) { s.render = r; },
            "render." + std::string(row.key));
    }
    ImGui::PopItemWidth();
}

}  // namespace sdfwb::ui
