#pragma once
// The field of an image file the scene names (a material's texture, the
// environment map's images): the name typed relative to the scene's folder
// or chosen with a file picker, a thumbnail of the image beside it, and the
// problems of files that cannot be read under the fields.

#include <string>

#include "ui/editor.h"
#include "ui/ui_state.h"

namespace sdfwb::ui {

// The field of the file named at JSON path `key`: its thumbnail (when
// ui.imageThumbnail has one), the name, and a "..." button that opens the
// picker in the scene's folder; a picked file is named relative to that
// folder. True when an edit was finished (Enter, leaving the field, a file
// picked), which is when the caller applies `name`.
bool imageFileField(UiState& ui, const scene::Scene& scene, const char* label, const std::string& key,
                    std::string& name);

// The scene's image files under `keyPrefix` that cannot be read, in red
// (their map or texture shows a magenta checkerboard meanwhile), as the last
// finished check (ui/scene_image_check.h) found.
void drawImageProblems(const Editor& editor, UiState& ui, const std::string& keyPrefix);

}  // namespace sdfwb::ui
