#include "ui/material_edits.h"

#include <imgui.h>

#include "ui/panels.h"

namespace sdfwb::ui {
namespace {

int materialIndex(const scene::Node& node) { return scene::fieldIndex(scene::kindSpec(node.kind), "material"); }

void reassignIn(scene::Node& node, const std::string& from, const std::string& to) {
    int index = materialIndex(node);
    if (index >= 0 && std::get<std::string>(node.fields[static_cast<size_t>(index)]) == from) {
        node.fields[static_cast<size_t>(index)] = to;
    }
    for (scene::Node& child : node.children) reassignIn(child, from, to);
}

int usersIn(const scene::Node& node, const std::string& name) {
    int index = materialIndex(node);
    int users = index >= 0 && std::get<std::string>(node.fields[static_cast<size_t>(index)]) == name ? 1 : 0;
    for (const scene::Node& child : node.children) users += usersIn(child, name);
    return users;
}

}  // namespace

void reassignMaterial(scene::Scene& scene, const std::string& from, const std::string& to) {
    reassignIn(scene.root, from, to);
    if (scene.environment.ground.material == from) scene.environment.ground.material = to;
}

int materialUsers(const scene::Scene& scene, const std::string& name) {
    return usersIn(scene.root, name) + (scene.environment.ground.material == name ? 1 : 0);
}

Problems removeMaterial(Editor& editor, const std::string& name, const std::string& replacement) {
    if (!editor.scene().findMaterial(name)) return {"materials: no material named \"" + name + "\""};
    if (replacement == name) return {"materials: \"" + name + "\" cannot replace itself"};
    return editor.apply("Remove material", [&](scene::Scene& s) {
        reassignMaterial(s, name, replacement);
        std::erase_if(s.materials, [&](const scene::Material& m) { return m.name == name; });
    });
}

void drawRemoveMaterialButton(Editor& editor, UiState& ui, size_t index) {
    const std::string name = editor.scene().materials[index].name;
    int users = materialUsers(editor.scene(), name);
    if (ImGui::SmallButton("Remove")) {
        if (users == 0) {
            reportProblems(ui, removeMaterial(editor, name, ""));
            return;
        }
        ImGui::OpenPopup("remove material");
    }
    if (!ImGui::BeginPopup("remove material")) return;
    ImGui::Text("\"%s\" is used %d time%s. Give its users instead:", name.c_str(), users, users == 1 ? "" : "s");
    if (ImGui::Selectable("(default material)")) reportProblems(ui, removeMaterial(editor, name, ""));
    for (const scene::Material& other : editor.scene().materials) {
        if (other.name != name && ImGui::Selectable(other.name.c_str())) {
            reportProblems(ui, removeMaterial(editor, name, other.name));
        }
    }
    ImGui::Separator();
    if (ImGui::Selectable("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace sdfwb::ui
