#pragma once
// What a module executable runs: each module (app/modules/*_module.cpp)
// defines runCommand for the commands moduleOf assigns to it.

#include "app/command_line.h"

namespace sdfwb::app {

// Runs `line.command`; returns the exit status.
int runCommand(const CommandLine& line);

// For a command of another module (the module was started by hand): a
// one-line error and kExitError.
int refuseCommand(const CommandLine& line);

}  // namespace sdfwb::app
