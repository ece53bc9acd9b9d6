// The primitive library panel: insert a saved subtree, save the selection.

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/panels.h"
#include "ui/primitive_library.h"

namespace sdfwb::ui {

void drawLibraryPanel(Editor& editor, UiState& ui) {
    const scene::Node* selected = editor.selectedNode();
    ImGui::SetNextItemWidth(-70);
    ImGui::InputTextWithHint("##name", "name for the selection", &ui.libraryName);
    ImGui::SameLine();
    ImGui::BeginDisabled(!selected || ui.libraryName.empty());
    if (ImGui::Button("Save")) {
        try {
            saveLibraryEntry(ui.libraryName, *selected);
            ui.info("saved \"" + ui.libraryName + "\" to the primitive library");
            ui.libraryName.clear();
        } catch (const std::exception& error) {
            ui.error(error.what());
        }
    }
    ImGui::EndDisabled();
    for (const std::string& name : libraryEntries()) {
        ImGui::PushID(name.c_str());
        if (ImGui::SmallButton("Insert")) {
            try {
                std::optional<NodePath> target = editor.selection();
                scene::Node node = loadLibraryEntry(name);
                const scene::Node* at = target ? findNode(editor.scene().root, *target) : nullptr;
                bool into = at && scene::kindSpec(at->kind).maxChildren < 0;
                NodePath parent = into || !target || target->empty() ? target.value_or(NodePath{}) : parentOf(*target);
                reportProblems(ui, editor.insert(parent, -1, std::move(node)));
            } catch (const std::exception& error) {
                ui.error(error.what());
            }
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(name.c_str());
        ImGui::SameLine(ImGui::GetContentRegionAvail().x + ImGui::GetCursorPosX() - 20);
        if (ImGui::SmallButton("x")) removeLibraryEntry(name);
        ImGui::PopID();
    }
}

}  // namespace sdfwb::ui
