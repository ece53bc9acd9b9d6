#pragma once
// Edits of the material list that follow its references: renaming a material
// renames what uses it, and removing a material in use reassigns its users
// (nodes and the ground) to another material instead of being refused.

#include <string>

#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// Points every reference to material `from` (node fields and the ground) at `to`.
void reassignMaterial(scene::Scene& scene, const std::string& from, const std::string& to);

// How many nodes use the material, plus one when the ground does.
int materialUsers(const scene::Scene& scene, const std::string& name);

// Removes the material, its users reassigned to `replacement` ("" the
// default material), in one undo step.
Problems removeMaterial(Editor& editor, const std::string& name, const std::string& replacement);

// The Remove button of material `index`: removes an unused material at once;
// for one in use, a popup asks which material its users get instead.
void drawRemoveMaterialButton(Editor& editor, UiState& ui, size_t index);

}  // namespace sdfwb::ui
