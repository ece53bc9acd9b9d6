#pragma once
// The viewport panel: toolbar (backend, compare mode, heat view, statistics,
// frame all, snapshot), the image, the orbit camera controls and the
// statistics overlay. Records the image size and interaction in app.view.

#include "app/gui/app_state.h"

namespace sdfwb::app::gui {

void drawViewportPanel(AppState& app);
// The height of the band along an image's bottom that says it is not the
// current state's (or whose it is); what else sits at the bottom goes above it.
float slotNoteHeight();
// Aims the camera at the whole scene (undoable).
void frameAll(AppState& app);

}  // namespace sdfwb::app::gui
