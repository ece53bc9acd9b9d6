// sdf-workbench implicitize and groebner (GMP, FLINT).

#include "app/algebra_commands.h"
#include "app/module_commands.h"

namespace sdfwb::app {

int runCommand(const CommandLine& line) {
    switch (line.command) {
    case Command::Implicitize: return runImplicitize(line.implicitize);
    case Command::Groebner: return runGroebner(line.groebner);
    default: return refuseCommand(line);
    }
}

}  // namespace sdfwb::app
