#include "app/user_files/user_paths.h"

#include <cstdlib>

namespace sdfwb::app {
namespace {

std::filesystem::path xdg(const char* variable, const char* fallback) {
    const char* value = std::getenv(variable);
    if (value && *value) return std::filesystem::path(value) / "sdf-workbench";
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home ? home : ".") / fallback / "sdf-workbench";
}

}  // namespace

std::filesystem::path configDirectory() { return xdg("XDG_CONFIG_HOME", ".config"); }
std::filesystem::path stateDirectory() { return xdg("XDG_STATE_HOME", ".local/state"); }

}  // namespace sdfwb::app
