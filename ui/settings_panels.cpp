// Render settings and environment: the scene-wide values of the format's
// "render" and "environment" objects, one widget per row of their settings
// tables (scene/settings_table.h).

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "program/scene_images.h"

#include "ui/image_file_field.h"
#include "ui/panel_widgets.h"
#include "ui/panels.h"
#include "ui/setting_widgets.h"

namespace sdfwb::ui {

void drawRenderSettingsPanel(Editor& editor, UiState& ui) {
    scene::RenderSettings r = editor.scene().render;
    auto set = [&](WidgetEdit edit, std::string_view key) {
        commitEdit(
            editor, ui, edit, "Edit render settings", [&r](scene::Scene& s) { s.render = r; },
            "render." + std::string(key));
    };
    ImGui::PushItemWidth(-130);
    for (const scene::Setting<scene::RenderSettings>& row : scene::renderSettings()) {
        if (row.widget.section != scene::EditorSection::Panel) continue;
        // in pixel mode epsilon counts sub-sample footprints: drag by hundredths
        bool pixels = row.key == "epsilon" && r.epsilonMode == scene::EpsilonMode::Pixel;
        set(settingWidget(row, r, pixels ? 0.01 : 0.0), row.key);
    }
    ImGui::PopItemWidth();
}

void drawEnvironmentPanel(Editor& editor, UiState& ui) {
    scene::Environment e = editor.scene().environment;
    auto set = [&](WidgetEdit edit, const std::string& path) {
        commitEdit(
            editor, ui, edit, "Edit environment", [&e](scene::Scene& s) { s.environment = e; }, path);
    };
    ImGui::PushItemWidth(-130);
    std::vector<program::SceneImageFile> files = program::environmentFiles(editor.scene());
    for (const scene::Setting<scene::Environment>& row : scene::environmentSettings()) {
        std::string path = "environment." + std::string(row.key);
        if (row.type != scene::SettingType::ImageFile) {
            set(settingWidget(row, e), path);
            continue;
        }
        // only the files the chosen map reads, typed relative to the scene's folder
        bool used = std::any_of(files.begin(), files.end(), [&](const auto& f) { return f.key == path; });
        if (!used) continue;
        std::string& name = e.*std::get<std::string scene::Environment::*>(row.member);
        if (imageFileField(ui, editor.scene(), std::string(row.label).c_str(), path, name)) set({true, true}, path);
    }
    drawImageProblems(editor, ui, "environment.");
    ImGui::Separator();
    ImGui::TextDisabled("Ground plane");
    for (const scene::Setting<scene::Ground>& row : scene::groundSettings()) {
        set(settingWidget(row, e.ground), "environment.ground." + std::string(row.key));
    }
    const std::string& current = e.ground.material;
    if (ImGui::BeginCombo("material", current.empty() ? "(default)" : current.c_str())) {
        if (ImGui::Selectable("(default)", current.empty())) {
            e.ground.material.clear();
            set({true, true}, "environment.ground.material");
        }
        for (const scene::Material& m : editor.scene().materials) {
            if (ImGui::Selectable(m.name.c_str(), m.name == current)) {
                e.ground.material = m.name;
                set({true, true}, "environment.ground.material");
            }
        }
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
}

}  // namespace sdfwb::ui
