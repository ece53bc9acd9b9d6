#pragma once
// The whole command line: every subcommand and its options. The launcher
// (launcher_main.cpp) parses it to answer --help and bad arguments itself and
// to choose the module that runs the command (command_modules.h); that module
// (module_main.cpp) parses the same arguments again and runs it.

#include <optional>
#include <string>

#include "app/algebra_arguments.h"
#include "app/compare_arguments.h"
#include "app/gui/gui_arguments.h"
#include "app/mesh_arguments.h"
#include "app/parity_arguments.h"
#include "app/render_arguments.h"
#include "app/tradeoff_arguments.h"

namespace sdfwb::app {

enum class Command {
    Default,  // no subcommand: the window, or a snapshot without a display
    Render,
    Compare,
    Parity,
    Tradeoff,
    Mesh,
    Gui,
    Implicitize,
    Groebner,
};

struct CommandLine {
    Command command = Command::Default;
    std::string name;  // the subcommand as typed, "" for Default
    RenderArguments render;
    CompareArguments compare;
    ParityArguments parity;
    TradeoffArguments tradeoff;
    MeshArguments mesh;
    gui::GuiArguments gui;
    ImplicitizeArguments implicitize;
    GroebnerArguments groebner;
};

// Parses argv[1..] into `line`. Returns the exit status when parsing ends the
// run (--help printed, or a one-line error on stderr); nothing when
// `line.command` is to run.
std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& line);

}  // namespace sdfwb::app
