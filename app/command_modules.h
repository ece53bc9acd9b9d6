#pragma once
// Which executable runs which command. Each module links only the libraries
// its commands need, so `sdf-workbench --help`, a bad argument or an algebra
// command never loads the GL, image and GUI libraries (some 270 shared
// objects, about 0.25 s of CPU to relocate before main).

#include <string_view>

#include "app/command_line.h"

namespace sdfwb::app {

// The module's file name, next to the launcher.
std::string_view moduleOf(Command command);

// Replaces the launcher's process by the module with the same arguments (the
// process id stays, so signals and exit status reach the caller as before).
// Returns only on failure, with kExitError after a one-line message.
int startModule(std::string_view module, char** argv);

}  // namespace sdfwb::app
