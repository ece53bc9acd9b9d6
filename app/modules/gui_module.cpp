// sdf-workbench gui, and the default job: the window (GLFW, Dear ImGui, every
// engine library), or a snapshot when no window opens.

#include <cstdio>
#include <filesystem>

#include "app/command_errors.h"
#include "app/gui/gui_command.h"
#include "app/module_commands.h"
#include "app/render_command.h"

namespace sdfwb::app {
namespace {

// The window on the default scene when a display exists, otherwise (or when
// no window opens) a snapshot of the default scene.
int runDefaultJob() {
    if (gui::displayAvailable()) {
        int code = gui::runGui({});
        if (code != gui::kNoWindow) return code;
        std::fprintf(stderr, "sdf-workbench: no window; writing a snapshot instead\n");
    }
    RenderArguments snapshot;
    snapshot.output = (std::filesystem::current_path() / "sdf-workbench-default.png").string();
    return runRender(snapshot);
}

}  // namespace

int runCommand(const CommandLine& line) {
    switch (line.command) {
    case Command::Default: return runDefaultJob();
    case Command::Gui: {
        int code = gui::runGui(line.gui);
        return code == gui::kNoWindow ? kExitError : code;
    }
    default: return refuseCommand(line);
    }
}

}  // namespace sdfwb::app
