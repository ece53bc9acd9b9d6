#pragma once
// The primitive library as the library panel sees it: subtrees the user saved
// under a name, in the scene format's node form. The app gives the panel a
// folder of files (app/user_files/primitive_folder.h); the panel itself never
// touches the file system.

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::ui {

class PrimitiveLibrary {
public:
    virtual ~PrimitiveLibrary() = default;

    // Entry names, sorted; cheap to call every frame.
    virtual const std::vector<std::string>& entries() = 0;
    // Looks again for entries added or removed by other programs.
    virtual void refresh() = 0;

    // Saves `node` as `name` (letters, digits, space, '-', '_'); throws
    // std::runtime_error with one line naming the problem.
    virtual void save(const std::string& name, const scene::Node& node) = 0;
    // Throws scene::SceneError (invalid entry) or std::runtime_error (unreadable).
    virtual scene::Node load(const std::string& name) const = 0;
    // Deletes the entry, keeping it so restoreRemoved() can put it back;
    // throws std::runtime_error naming what failed.
    virtual void remove(const std::string& name) = 0;
    // The entry remove() deleted last, while it can be restored.
    virtual const std::optional<std::string>& removed() const = 0;
    virtual void restoreRemoved() = 0;
};

}  // namespace sdfwb::ui
