#include "app/command_modules.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "app/command_errors.h"

namespace sdfwb::app {

// The file names come from the build (app/CMakeLists.txt), where the module
// executables are defined.
std::string_view moduleOf(Command command) {
    switch (command) {
    case Command::Default:
    case Command::Gui: return SDFWB_GUI_MODULE;
    case Command::Render:
    case Command::Compare:
    case Command::Parity:
    case Command::Tradeoff: return SDFWB_RENDER_MODULE;
    case Command::Mesh: return SDFWB_MESH_MODULE;
    case Command::Implicitize:
    case Command::Groebner: return SDFWB_ALGEBRA_MODULE;
    }
    return SDFWB_GUI_MODULE;
}

int startModule(std::string_view module, char** argv) {
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) {
        std::cerr << "sdf-workbench: cannot find its own executable (/proc/self/exe): " << error.message() << "\n";
        return kExitError;
    }
    std::filesystem::path path = self.parent_path() / module;
    execv(path.c_str(), argv);
    std::cerr << "sdf-workbench: cannot start " << path.string() << ": " << std::strerror(errno) << "\n";
    return kExitError;
}

}  // namespace sdfwb::app
