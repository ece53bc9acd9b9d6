#pragma once
// The primitive library: subtrees the user saved under a name, one JSON file
// per entry in a folder (configDirectory()/primitives), in the scene format's
// node form. A file-system service the library panel is given: the folder
// is listed once and after each change made here (or refresh()), never per
// frame, and a removed entry can be put back until the next removal.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::ui {

class PrimitiveLibrary {
public:
    // The user's library (configDirectory()/primitives), or `folder`.
    PrimitiveLibrary();
    explicit PrimitiveLibrary(std::filesystem::path folder);

    // Entry names, sorted (the folder is listed on first use).
    const std::vector<std::string>& entries();
    // Lists the folder again (files added or removed by other programs).
    void refresh();

    // Saves `node` as `name` (letters, digits, space, '-', '_'); throws
    // std::runtime_error with one line naming the problem.
    void save(const std::string& name, const scene::Node& node);
    // Throws scene::SceneError (invalid entry) or std::runtime_error (unreadable).
    scene::Node load(const std::string& name) const;
    // Deletes the entry's file, keeping its text so restoreRemoved() can
    // write it back; throws std::runtime_error naming what failed.
    void remove(const std::string& name);
    // The entry remove() deleted last, while it can be restored.
    const std::optional<std::string>& removed() const { return removedName_; }
    void restoreRemoved();

private:
    std::filesystem::path fileOf(const std::string& name) const;

    std::filesystem::path folder_;
    std::optional<std::vector<std::string>> entries_;
    std::optional<std::string> removedName_;
    std::string removedText_;
};

}  // namespace sdfwb::ui
