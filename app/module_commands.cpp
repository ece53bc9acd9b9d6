#include "app/module_commands.h"

#include <iostream>

#include "app/command_errors.h"

namespace sdfwb::app {

int refuseCommand(const CommandLine& line) {
    std::cerr << "sdf-workbench: this module does not run '" << line.name << "'; run it through sdf-workbench\n";
    return kExitError;
}

}  // namespace sdfwb::app
