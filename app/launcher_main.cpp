// sdf-workbench: one executable, one subcommand per job. This launcher parses
// the command line and hands the run to the module made for the command
// (command_modules.h).

#include "app/command_line.h"
#include "app/command_modules.h"

int main(int argc, char** argv) {
    sdfwb::app::CommandLine line;
    if (std::optional<int> done = sdfwb::app::parseCommandLine(argc, argv, line)) {
        return *done;
    }
    return sdfwb::app::startModule(sdfwb::app::moduleOf(line.command), argv);
}
