#pragma once
// Where the workbench keeps the user's files (XDG base directories):
// configuration (primitive library, recent files) under $XDG_CONFIG_HOME
// (default ~/.config), state (autosave) under $XDG_STATE_HOME (default
// ~/.local/state), each in a "sdf-workbench" folder.

#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::ui {

std::filesystem::path configDirectory();
std::filesystem::path stateDirectory();

// Recent scene files, newest first, at most 8, those that still exist; kept in
// configDirectory()/recent.txt.
std::vector<std::string> loadRecentFiles();
// Moves `path` to the front and saves the list; errors are ignored (a recent
// list is a convenience, never a reason to fail a save).
void rememberRecentFile(const std::string& path);

}  // namespace sdfwb::ui
