#include "ui/file_browser.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace sdfwb::ui {
namespace fs = std::filesystem;

void FileBrowser::open(FolderLister lister, const fs::path& folder, const std::string& typed) {
    lister_ = std::move(lister);
    folder_ = folder;
    listing_ = lister_ ? lister_(folder_, extensions_) : FolderListing{};
    path = typed;
}

bool FileBrowser::draw(float reserveBelow) {
    ImGui::TextDisabled("%s", folder_.string().c_str());
    ImGui::BeginChild("entries", ImVec2(0, -reserveBelow - ImGui::GetFrameHeightWithSpacing()), true);
    fs::path next;
    bool accepted = false;
    if (ImGui::Selectable("..")) next = folder_.parent_path();
    for (const fs::path& folder : listing_.folders) {
        if (ImGui::Selectable((folder.filename().string() + "/").c_str())) next = folder;
    }
    for (const fs::path& file : listing_.files) {
        if (ImGui::Selectable(file.filename().string().c_str(), path == file.string(),
                              ImGuiSelectableFlags_AllowDoubleClick)) {
            path = file.string();
            accepted = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        }
    }
    if (listing_.omitted > 0) ImGui::TextDisabled("(%zu more entries not listed)", listing_.omitted);
    if (!listing_.error.empty()) ImGui::TextDisabled("%s", listing_.error.c_str());
    ImGui::EndChild();
    if (!next.empty()) open(lister_, next, path);
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##path", &path, ImGuiInputTextFlags_EnterReturnsTrue)) {
        std::error_code error;
        if (fs::is_directory(path, error)) {
            open(lister_, path, "");  // a folder typed: show it
        } else {
            accepted = true;
        }
    }
    return accepted;
}

}  // namespace sdfwb::ui
