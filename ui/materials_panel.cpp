// Materials: the scene's list, each editable (the thesis's R_A, R_D, R_E,
// alpha, L_E); add, rename (references follow) and remove (users reassigned,
// ui/material_edits.h).

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "program/scene_images.h"

#include "ui/image_file_field.h"
#include "ui/material_edits.h"
#include "ui/panel_widgets.h"
#include "ui/panels.h"
#include "ui/setting_widgets.h"

namespace sdfwb::ui {
void drawMaterialsPanel(Editor& editor, UiState& ui) {
    const scene::Scene& scene = editor.scene();
    if (ImGui::Button("Add material")) {
        std::string name;
        for (int i = 1; name.empty() || scene.findMaterial(name); ++i) name = "material " + std::to_string(i);
        reportProblems(ui, editor.apply("Add material", [&](scene::Scene& s) {
            scene::Material m;
            m.name = name;
            s.materials.push_back(m);
        }));
    }
    // the image fields shown: the files the materials' textures and bump maps read
    const std::vector<program::SceneImageFile> files = program::textureFiles(editor.scene());
    for (size_t i = 0; i < editor.scene().materials.size(); ++i) {
        scene::Material m = editor.scene().materials[i];
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::CollapsingHeader(m.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            auto set = [&, i](const char* label, WidgetEdit edit) {
                commitEdit(editor, ui, edit, label, [&m, i](scene::Scene& s) { s.materials[i] = m; });
            };
            std::string name = m.name;
            if (ImGui::InputText("name", &name, ImGuiInputTextFlags_EnterReturnsTrue) && name != m.name) {
                std::string old = m.name;
                reportProblems(ui, editor.apply("Rename material", [&](scene::Scene& s) {
                    s.materials[i].name = name;
                    reassignMaterial(s, old, name);
                }));
            }
            const std::string path = "materials[" + std::to_string(i) + "]";
            for (const scene::Setting<scene::Material>& row : scene::materialSettings()) {
                std::string key = path + "." + std::string(row.key);
                if (row.type != scene::SettingType::ImageFile) {
                    set("Edit material", settingWidget(row, m));  // the name has its own field above
                } else if (std::any_of(files.begin(), files.end(), [&](const auto& f) { return f.key == key; })) {
                    std::string& name = m.*std::get<std::string scene::Material::*>(row.member);
                    if (imageFileField(ui, editor.scene(), std::string(row.label).c_str(), key, name))
                        set("Edit material", {true, true});
                    drawImageProblems(editor, ui, key);
                }
            }
            drawRemoveMaterialButton(editor, ui, i);
        }
        ImGui::PopID();
    }
}

}  // namespace sdfwb::ui
