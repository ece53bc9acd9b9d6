// The main of every module executable (command_modules.h): the same command
// line as the launcher's, run by the module's runCommand.

#include "app/command_line.h"
#include "app/module_commands.h"
#include "io/temporary_files.h"

int main(int argc, char** argv) {
    sdfwb::io::removeTemporariesOnTermination();
    sdfwb::app::CommandLine line;
    if (std::optional<int> done = sdfwb::app::parseCommandLine(argc, argv, line)) {
        return *done;
    }
    return sdfwb::app::runCommand(line);
}
