#include "ui/image_file_field.h"

#include <filesystem>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "program/scene_images.h"
#include "ui/panel_widgets.h"

namespace sdfwb::ui {
namespace {

constexpr const char* kPickerTitle = "Choose image";

// The picker's modal window while it is open for the field at ui.imagePickerKey;
// true when a file was chosen (then named in `name`).
bool drawImagePicker(UiState& ui, const scene::Scene& scene, std::string& name) {
    ImGui::SetNextWindowSize(ImVec2(560, 380), ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(kPickerTitle)) {
        ui.imagePickerKey.clear();  // closed some other way
        return false;
    }
    bool accept = ui.imagePicker.draw(ImGui::GetFrameHeightWithSpacing());
    accept = ImGui::Button("Choose") || accept;
    ImGui::SameLine();
    bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    bool chosen = accept && !ui.imagePicker.path.empty();
    if (chosen) name = program::sceneFileName(scene, ui.imagePicker.path);
    if (accept || cancel) {
        ui.imagePickerKey.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    return chosen;
}

}  // namespace

bool imageFileField(UiState& ui, const scene::Scene& scene, const char* label, const std::string& key,
                    std::string& name) {
    ImGui::PushID(key.c_str());
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const float side = ImGui::GetFrameHeight();
    float width = ImGui::CalcItemWidth();
    if (void* thumbnail = ui.imageThumbnail ? ui.imageThumbnail(key) : nullptr) {
        ImGui::Image(thumbnail, ImVec2(side, side));
        if (ImGui::IsItemHovered()) {
            ImGui::BeginTooltip();
            ImGui::Image(thumbnail, ImVec2(160, 160));
            ImGui::TextUnformatted(name.c_str());
            ImGui::EndTooltip();
        }
        ImGui::SameLine(0, spacing);
        width -= side + spacing;
    }
    const char* browse = "...";
    width -= ImGui::CalcTextSize(browse).x + 2 * ImGui::GetStyle().FramePadding.x + spacing;
    ImGui::SetNextItemWidth(width);
    ImGui::InputTextWithHint("##name", "image file, relative to the scene", &name);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "JSON key %s\nPNG, JPEG, TIFF or EXR; relative to the scene file's folder\n"
            "Enter or leaving the field applies it",
            key.c_str());
    }
    bool finished = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::SameLine(0, spacing);
    if (ImGui::Button(browse)) {
        std::filesystem::path current = program::sceneFilePath(scene, name);
        std::filesystem::path folder = name.empty() ? program::sceneFilePath(scene, ".") : current.parent_path();
        ui.imagePicker.open(ui.listFolder, std::filesystem::absolute(folder), name.empty() ? "" : current.string());
        ui.imagePickerKey = key;
        ImGui::OpenPopup(kPickerTitle);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Choose an image file");
    ImGui::SameLine(0, spacing);
    ImGui::TextUnformatted(label);
    if (ui.imagePickerKey == key && drawImagePicker(ui, scene, name)) finished = true;
    ImGui::PopID();
    return finished;
}

void drawImageProblems(const Editor& editor, UiState& ui, const std::string& keyPrefix) {
    ui.imageCheck->request(editor.scene());
    if (ui.imageCheck->pending()) ImGui::TextDisabled("reading images...");
    for (const std::string& problem : ui.imageCheck->problems()) {
        if (problem.starts_with(keyPrefix)) problemText(problem);
    }
}

}  // namespace sdfwb::ui
