#pragma once
// `sdf-workbench gui [SCENE] [--script FILE] [--screenshot OUT.png --frames N]`:
// the workbench window.

#include "app/gui/gui_arguments.h"

namespace sdfwb::app::gui {

// Exit code returned when no window could be opened (GLFW init failed).
inline constexpr int kNoWindow = -1;

// Runs the window until quit; returns the exit code (non-zero after a
// script error), or kNoWindow when GLFW cannot open a window.
int runGui(const GuiArguments& arguments);

}  // namespace sdfwb::app::gui
