#pragma once
// `sdf-workbench gui`: its options, and whether a display exists.
// Light on purpose: the launcher parses every command line with these alone
// (app/command_line.h) before it starts the module that runs the command.

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app::gui {

struct GuiArguments {
    std::string scene;       // "" = the embedded default scene
    std::string script;      // run this script (docs/gui-script.md)
    std::string screenshot;  // save the window after `frames` frames and quit
    int frames = 3;
    int width = 1280;  // window size in screen coordinates
    int height = 800;
};

CLI::App* addGuiCommand(CLI::App& app, GuiArguments& arguments);

// Whether a display server is announced (DISPLAY or WAYLAND_DISPLAY).
bool displayAvailable();

}  // namespace sdfwb::app::gui
