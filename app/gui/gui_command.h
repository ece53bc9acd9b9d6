#pragma once
// `sdf-workbench gui [SCENE] [--script FILE] [--screenshot OUT.png --frames N]`:
// the workbench window.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app::gui {

struct GuiArguments {
    std::string scene;       // "" = the embedded default scene
    std::string script;      // run this script (docs/gui-script.md)
    std::string screenshot;  // save the window after `frames` frames and quit
    int frames = 3;
    int width = 1280;        // window size in screen coordinates
    int height = 800;
};

CLI::App* addGuiCommand(CLI::App& app, GuiArguments& arguments);

// Whether a display server is announced (DISPLAY or WAYLAND_DISPLAY).
bool displayAvailable();

// Exit code returned when no window could be opened (GLFW init failed).
inline constexpr int kNoWindow = -1;

// Runs the window until quit; returns the exit code (non-zero after a
// script error), or kNoWindow when GLFW cannot open a window.
int runGui(const GuiArguments& arguments);

}  // namespace sdfwb::app::gui
