// sdf-workbench: one executable, one subcommand per job.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "app/algebra_commands.h"
#include "app/command_errors.h"
#include "app/formula_arguments.h"
#include "app/compare_command.h"
#include "app/gui/gui_command.h"
#include "app/mesh_command.h"
#include "app/parity_command.h"
#include "app/render_command.h"
#include "app/tradeoff_command.h"
#include "io/temporary_files.h"

namespace {

// With no subcommand: the workbench window on the default scene when a display
// exists, otherwise (or when no window opens) a snapshot of the default scene.
int runDefaultJob() {
    if (sdfwb::app::gui::displayAvailable()) {
        int code = sdfwb::app::gui::runGui({});
        if (code != sdfwb::app::gui::kNoWindow) {
            return code;
        }
        std::fprintf(stderr, "sdf-workbench: no window; writing a snapshot instead\n");
    }
    sdfwb::app::RenderArguments snapshot;
    snapshot.output = (std::filesystem::current_path() / "sdf-workbench-default.png").string();
    return sdfwb::app::runRender(snapshot);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"SDF Workbench: model and render surfaces defined by signed distance functions"};
    app.require_subcommand(0, 1);
    app.footer(
        "Without a command: the workbench window on the built-in default scene when a display is available,\n"
        "otherwise a snapshot of it written to ./sdf-workbench-default.png.\n"
        "'sdf-workbench COMMAND --help' describes one command; docs/ in the source tree describes the rest.");
    sdfwb::app::RenderArguments renderArguments;
    CLI::App* render = sdfwb::app::addRenderCommand(app, renderArguments);
    sdfwb::app::CompareArguments compareArguments;
    CLI::App* compare = sdfwb::app::addCompareCommand(app, compareArguments);
    sdfwb::app::ParityArguments parityArguments;
    CLI::App* parity = sdfwb::app::addParityCommand(app, parityArguments);
    sdfwb::app::MeshArguments meshArguments;
    CLI::App* mesh = sdfwb::app::addMeshCommand(app, meshArguments);
    sdfwb::app::gui::GuiArguments guiArguments;
    CLI::App* gui = sdfwb::app::gui::addGuiCommand(app, guiArguments);
    sdfwb::app::ImplicitizeArguments implicitizeArguments;
    CLI::App* implicitize = sdfwb::app::addImplicitizeCommand(app, implicitizeArguments);
    sdfwb::app::GroebnerArguments groebnerArguments;
    CLI::App* groebner = sdfwb::app::addGroebnerCommand(app, groebnerArguments);
    sdfwb::app::TradeoffArguments tradeoffArguments;
    CLI::App* tradeoff = sdfwb::app::addTradeoffCommand(app, tradeoffArguments);
    sdfwb::io::removeTemporariesOnTermination();
    std::vector<std::string> arguments = sdfwb::app::formulasAsPositionals(
        std::vector<std::string>(argv + 1, argv + argc), app, {"groebner", "implicitize"});
    std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& error) {
        // --help and --version are "errors" with exit code 0
        if (error.get_exit_code() == 0) return app.exit(error);
        // one line, and the exit code of every other bad input
        std::cerr << "sdf-workbench: " << error.what() << " (see --help)\n";
        return sdfwb::app::kExitError;
    }
    if (implicitize->parsed()) {
        return sdfwb::app::runImplicitize(implicitizeArguments);
    }
    if (groebner->parsed()) {
        return sdfwb::app::runGroebner(groebnerArguments);
    }
    if (gui->parsed()) {
        int code = sdfwb::app::gui::runGui(guiArguments);
        return code == sdfwb::app::gui::kNoWindow ? sdfwb::app::kExitError : code;
    }
    if (mesh->parsed()) {
        return sdfwb::app::runMesh(meshArguments);
    }
    if (render->parsed()) {
        return sdfwb::app::runRender(renderArguments);
    }
    if (compare->parsed()) {
        return sdfwb::app::runCompare(compareArguments);
    }
    if (tradeoff->parsed()) {
        return sdfwb::app::runTradeoff(tradeoffArguments);
    }
    if (parity->parsed()) {
        return sdfwb::app::runParity(parityArguments);
    }
    return runDefaultJob();
}
