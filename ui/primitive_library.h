#pragma once
// The primitive library: subtrees the user saved under a name, one JSON file
// per entry in configDirectory()/primitives, in the scene format's node form.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::ui {

// Entry names, sorted.
std::vector<std::string> libraryEntries();
// Saves `node` as `name` (letters, digits, space, '-', '_'); throws
// std::runtime_error with one line naming the problem.
void saveLibraryEntry(const std::string& name, const scene::Node& node);
// Throws scene::SceneError (invalid entry) or std::runtime_error (unreadable).
scene::Node loadLibraryEntry(const std::string& name);
void removeLibraryEntry(const std::string& name);

}  // namespace sdfwb::ui
