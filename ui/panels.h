#pragma once
// The editor's panels: functions over the Editor (the scene and its history)
// and the UiState, drawn with Dear ImGui inside the current window. They edit
// only through the Editor, so every change is validated and undoable, and
// they hold no state of their own: they run in tests without a window.

#include <functional>

#include <imgui.h>

#include "ui/editor.h"
#include "ui/primitive_library.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// A texture showing the subtree at `path` (null while none is ready).
using ThumbnailLookup = std::function<ImTextureID(const NodePath& path, const scene::Node& node)>;

// The tree of nodes: select, rename, add, wrap, duplicate, delete, and drag
// and drop to reparent and reorder. Thumbnails when `thumbnails` is set.
void drawSceneTree(Editor& editor, UiState& ui, const ThumbnailLookup& thumbnails);

// The selected node's fields, driven by the node-kind field table.
void drawInspector(Editor& editor, UiState& ui);

void drawMaterialsPanel(Editor& editor, UiState& ui);
void drawLightsPanel(Editor& editor, UiState& ui);
void drawRenderSettingsPanel(Editor& editor, UiState& ui);
void drawEnvironmentPanel(Editor& editor, UiState& ui);
// The primitive library (ui/primitive_library.h): insert an entry next to or
// into the selection, save the selection under ui.libraryName, remove an
// entry (with an Undo until the next removal).
void drawLibraryPanel(Editor& editor, UiState& ui, PrimitiveLibrary& library);

// The Add menu's items (primitives and n-ary booleans) and the Wrap menu's
// (every kind that takes children); each calls Editor::add or Editor::wrap on
// the selection and reports refused edits to `ui`.
void drawAddMenuItems(Editor& editor, UiState& ui);
void drawWrapMenuItems(Editor& editor, UiState& ui);

// The Problems window (ui/problems.h) while ui.showProblems is set.
void drawProblemsWindow(Editor& editor, UiState& ui);

// Shows problems of a refused edit as UI messages (nothing when empty).
void reportProblems(UiState& ui, const Problems& problems);

}  // namespace sdfwb::ui
