// sdf-workbench mesh (OpenVDB).

#include "app/mesh_command.h"
#include "app/module_commands.h"

namespace sdfwb::app {

int runCommand(const CommandLine& line) {
    if (line.command == Command::Mesh) return runMesh(line.mesh);
    return refuseCommand(line);
}

}  // namespace sdfwb::app
