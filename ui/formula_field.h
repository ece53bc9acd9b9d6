#pragma once
// The inspector's editor for FieldType::Formula fields (sdf, implicit and
// polynomial nodes): a multiline text box whose every change is tried on the
// scene through the Editor, one undo step per editing session, with the
// reason a draft is refused shown in red under the box.

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

}  // namespace sdfwb::ui
