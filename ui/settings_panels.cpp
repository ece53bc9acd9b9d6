// Render settings and environment: the scene-wide values of the format's
// "render" and "environment" objects.

#include <imgui.h>

#include "ui/panel_widgets.h"
#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

template <typename Enum, size_t N>
bool enumCombo(const char* label, Enum& value, const char* const (&names)[N]) {
    int index = static_cast<int>(value);
    bool changed = ImGui::Combo(label, &index, names, static_cast<int>(N));
    if (changed) value = static_cast<Enum>(index);
    return changed;
}

WidgetEdit dragInt(const char* label, int& value, float speed, int minimum, int maximum) {
    bool changed = ImGui::DragInt(label, &value, speed, minimum, maximum);
    return {changed, ImGui::IsItemDeactivatedAfterEdit()};
}

// A combo or checkbox: each change is its own undo step.
WidgetEdit discrete(bool changed) { return {changed, changed}; }

}  // namespace

void drawRenderSettingsPanel(Editor& editor, UiState& ui) {
    scene::RenderSettings r = editor.scene().render;
    auto set = [&](WidgetEdit edit) {
        commitEdit(editor, ui, edit, "Edit render settings", [&r](scene::Scene& s) { s.render = r; });
    };
    ImGui::PushItemWidth(-130);
    set(dragInt("AA level", r.aa, 0.05f, 1, scene::kMaxAa));
    set(dragInt("snapshot width", r.width, 1.0f, 1, scene::kMaxImageSize));
    set(dragInt("snapshot height", r.height, 1.0f, 1, scene::kMaxImageSize));
    set(discrete(enumCombo("shadows", r.shadows, scene::kShadowModeNames)));
    set(dragInt("shadow steps", r.shadowSteps, 0.5f, 1, scene::kMaxShadowSteps));
    set(dragInt("AO samples", r.aoSamples, 0.1f, 0, scene::kMaxAoSamples));
    set(dragReal("AO distance", r.aoDistance, 0.01, 1e-4, 1e6));
    set(discrete(enumCombo("lighting", r.lighting, scene::kLightingModelNames)));
    set(dragInt("max steps", r.maxSteps, 1.0f, 1, scene::kMaxSteps));
    set(dragReal("max distance", r.maxDistance, 0.5, 1e-3, 1e9));
    set(discrete(enumCombo("epsilon mode", r.epsilonMode, scene::kEpsilonModeNames)));
    set(dragReal("epsilon", r.epsilon, r.epsilonMode == scene::EpsilonMode::Pixel ? 0.01 : 1e-5, 1e-9, 1e6, "%.5g"));
    ImGui::PopItemWidth();
}

void drawEnvironmentPanel(Editor& editor, UiState& ui) {
    scene::Environment e = editor.scene().environment;
    auto set = [&](WidgetEdit edit) {
        commitEdit(editor, ui, edit, "Edit environment", [&e](scene::Scene& s) { s.environment = e; });
    };
    ImGui::PushItemWidth(-130);
    set(colorEdit("ambient light", e.ambient));
    set(colorEdit("background", e.background));
    ImGui::Separator();
    ImGui::TextDisabled("Ground plane");
    set(discrete(ImGui::Checkbox("enabled", &e.ground.enabled)));
    set(dragReal("height", e.ground.height, 0.01, -1e6, 1e6));
    set(discrete(enumCombo("pattern", e.ground.pattern, scene::kGroundPatternNames)));
    set(dragReal("cell size", e.ground.cellSize, 0.01, 1e-4, 1e6));
    set(dragReal("line width", e.ground.lineWidth, 0.001, 0.0, 1e6));
    set(colorEdit("second colour", e.ground.secondColor));
    const std::string& current = e.ground.material;
    if (ImGui::BeginCombo("material", current.empty() ? "(default)" : current.c_str())) {
        if (ImGui::Selectable("(default)", current.empty())) {
            e.ground.material.clear();
            set({true, true});
        }
        for (const scene::Material& m : editor.scene().materials) {
            if (ImGui::Selectable(m.name.c_str(), m.name == current)) {
                e.ground.material = m.name;
                set({true, true});
            }
        }
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
}

}  // namespace sdfwb::ui
