#pragma once
// The window's layout at any size (1280x800 is the design size): menu bar,
// scene tree and library on the left, viewport in the middle, inspector tabs
// (node, materials, lights, render, environment) on the right, status bar.

#include "app/gui/app_state.h"

namespace sdfwb::app::gui {

void drawMainWindow(AppState& app);

// Keyboard shortcuts from the GLFW key presses queued in app.keyPresses
// (GLFW key codes: ImGui 1.86 names only a few letters); ignored while a
// text field has focus.
void handleShortcuts(AppState& app);

// Saves the window as drawn at the end of this frame to the next free
// sdf-workbench-window-N.png in the working directory.
void saveWindowPicture(AppState& app);

}  // namespace sdfwb::app::gui
