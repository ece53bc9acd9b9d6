#include "app/gui/gui_arguments.h"

#include <cstdlib>

namespace sdfwb::app::gui {

CLI::App* addGuiCommand(CLI::App& app, GuiArguments& arguments) {
    CLI::App* gui = app.add_subcommand("gui", "Open the workbench window (needs a display)");
    gui->add_option("scene", arguments.scene, "Scene file to open (default: the embedded default scene)");
    CLI::Option* script =
        gui->add_option("--script", arguments.script, "Run a script of GUI commands (docs/gui-script.md)");
    // a script decides itself when to take screenshots and quit
    gui->add_option("--screenshot", arguments.screenshot,
                    "Save the window to this PNG after --frames frames, then quit")
        ->excludes(script);
    gui->add_option("--frames", arguments.frames, "Frames to draw before --screenshot (it also waits until idle)")
        ->check(CLI::NonNegativeNumber);
    return gui;
}

bool displayAvailable() {
    auto set = [](const char* name) {
        const char* value = std::getenv(name);
        return value && *value;
    };
    return set("DISPLAY") || set("WAYLAND_DISPLAY");
}

}  // namespace sdfwb::app::gui
