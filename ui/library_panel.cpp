// The primitive library panel: insert a saved subtree, save the selection.

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/panels.h"
#include "ui/placement.h"
#include "ui/primitive_library.h"

namespace sdfwb::ui {

void drawLibraryPanel(Editor& editor, UiState& ui, PrimitiveLibrary& library) {
    const scene::Node* selected = editor.selectedNode();
    ImGui::SetNextItemWidth(-70);
    ImGui::InputTextWithHint("##name", "name for the selection", &ui.libraryName);
    ImGui::SameLine();
    ImGui::BeginDisabled(!selected || ui.libraryName.empty());
    if (ImGui::Button("Save")) {
        try {
            library.save(ui.libraryName, *selected);
            ui.info("saved \"" + ui.libraryName + "\" to the primitive library");
            ui.libraryName.clear();
        } catch (const std::exception& error) {
            ui.error(error.what());
        }
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::SmallButton("Refresh")) library.refresh();
    if (const std::optional<std::string>& removed = library.removed()) {
        ImGui::TextDisabled("removed \"%s\"", removed->c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Undo")) {
            try {
                library.restoreRemoved();
            } catch (const std::exception& error) {
                ui.error(error.what());
            }
        }
    }
    // a copy: removing an entry below changes the listing
    const std::vector<std::string> names = library.entries();
    for (const std::string& name : names) {
        ImGui::PushID(name.c_str());
        if (ImGui::SmallButton("Insert")) {
            try {
                std::optional<NodePath> target = editor.selection();
                scene::Node node = library.load(name);
                const scene::Node* at = target ? findNode(editor.scene().root, *target) : nullptr;
                bool into = at && scene::kindSpec(at->kind).maxChildren < 0;
                NodePath parent = into || !target || target->empty() ? target.value_or(NodePath{}) : parentOf(*target);
                reportProblems(ui, insertPlaced(editor, parent, -1, std::move(node)));
            } catch (const std::exception& error) {
                ui.error(error.what());
            }
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(name.c_str());
        ImGui::SameLine(ImGui::GetContentRegionAvail().x + ImGui::GetCursorPosX() - 20);
        if (ImGui::SmallButton("x")) {
            try {
                library.remove(name);
            } catch (const std::exception& error) {
                ui.error(error.what());
            }
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove from the library (Undo puts it back)");
        ImGui::PopID();
    }
}

}  // namespace sdfwb::ui
