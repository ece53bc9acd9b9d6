#pragma once
// Formula fields (sdf, implicit and polynomial nodes) as they are typed: in
// the inspector, a multiline text box whose every change is tried on the
// scene through the Editor, one undo step per editing session; in the Add
// menu, a draft that becomes a new node once it is valid. Either shows the
// reason a draft is refused in red under the box.

#include <string>
#include <string_view>

#include "scene/node_kinds.h"
#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// Tries `text` as the value of formula field `field` of the node at `path`.
// Applied: returns "" (consecutive calls with the same `mergeKey` are one undo
// step until Editor::endMerge). Refused: the scene is unchanged and the result
// is the reason, as checkField words it ("column 13: expected an expression"),
// or the editor's problems when the formula itself is fine.
std::string tryFormulaText(Editor& editor, const NodePath& path, const scene::FieldSpec& field,
                           const std::string& text, std::string_view mergeKey);

// Draws the field. While the box is active ImGui keeps the typed draft and
// hands it back every frame it differs from the scene, so a refused draft is
// retried (and its message refreshed) without state outside ImGui; leaving
// the box ends the undo merge and shows the scene's (last valid) formula again.
void drawFormulaField(Editor& editor, UiState& ui, const NodePath& path, const scene::FieldSpec& field,
                      const std::string& value);

// The kind's formula field, or nullptr for a kind without one.
const scene::FieldSpec* formulaField(const scene::KindSpec& kind);

// Adds a new `kind` node (sdf, implicit or polynomial) whose formula field is
// `formula`, where Editor::add puts it. Refused: the scene is unchanged and
// the problems say why, the formula's own reason first ("column 9: ...").
Problems addFormulaNode(Editor& editor, const scene::KindSpec& kind, const std::string& formula);

// The Add menu's entry for a kind with a formula field: a submenu holding a
// text box for the formula (a draft kept in ui.addFormulaDrafts), its problem
// in red as it is typed, and an Add button, which Enter also presses.
void drawAddFormulaMenu(Editor& editor, UiState& ui, const scene::KindSpec& kind);

}  // namespace sdfwb::ui
