#include "app/command_line.h"

#include <algorithm>
#include <iostream>
#include <utility>
#include <vector>

#include "app/command_errors.h"
#include "app/formula_arguments.h"

namespace sdfwb::app {

std::optional<int> parseCommandLine(int argc, char** argv, CommandLine& line) {
    CLI::App app{"SDF Workbench: model and render surfaces defined by signed distance functions"};
    app.require_subcommand(0, 1);
    app.footer(
        "Without a command: the workbench window on the built-in default scene when a display is available,\n"
        "otherwise a snapshot of it written to ./sdf-workbench-default.png.\n"
        "'sdf-workbench COMMAND --help' describes one command; docs/ in the source tree describes the rest.");
    const std::pair<CLI::App*, Command> commands[] = {
        {addRenderCommand(app, line.render), Command::Render},
        {addCompareCommand(app, line.compare), Command::Compare},
        {addParityCommand(app, line.parity), Command::Parity},
        {addMeshCommand(app, line.mesh), Command::Mesh},
        {gui::addGuiCommand(app, line.gui), Command::Gui},
        {addImplicitizeCommand(app, line.implicitize), Command::Implicitize},
        {addGroebnerCommand(app, line.groebner), Command::Groebner},
        {addTradeoffCommand(app, line.tradeoff), Command::Tradeoff},
    };
    std::vector<std::string> arguments =
        formulasAsPositionals(std::vector<std::string>(argv + 1, argv + argc), app, {"groebner", "implicitize"});
    std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& error) {
        // --help and --version are "errors" with exit code 0
        if (error.get_exit_code() == 0) return app.exit(error);
        // one line, naming the command it is about, and the exit code of every other bad input
        std::string where = "sdf-workbench";
        for (const auto& [subcommand, command] : commands) {
            if (subcommand->parsed()) where += " " + subcommand->get_name();
        }
        std::cerr << where << ": " << error.what() << " (see " << (where == "sdf-workbench" ? "" : where + " ")
                  << "--help)\n";
        return kExitError;
    }
    for (const auto& [subcommand, command] : commands) {
        if (subcommand->parsed()) {
            line.command = command;
            line.name = subcommand->get_name();
        }
    }
    return std::nullopt;
}

}  // namespace sdfwb::app
