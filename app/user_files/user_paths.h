#pragma once
// Where the workbench keeps the user's files (XDG base directories):
// configuration (primitive library, recent files) under $XDG_CONFIG_HOME
// (default ~/.config), state (autosave) under $XDG_STATE_HOME (default
// ~/.local/state), each in a "sdf-workbench" folder.

#include <filesystem>

namespace sdfwb::app {

std::filesystem::path configDirectory();
std::filesystem::path stateDirectory();

}  // namespace sdfwb::app
