#pragma once
// Recent scene files, newest first, at most 8, kept in a text file
// (configDirectory()/recent.txt). The list is read on first use and on
// refresh() (the File menu refreshes it when "Open recent" opens), never per
// frame; files that no longer exist leave it then.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::app {

class RecentFiles {
public:
    RecentFiles();  // the user's list
    explicit RecentFiles(std::filesystem::path file);

    const std::vector<std::string>& entries();
    void refresh();
    // Moves `path` to the front and saves the list; errors are ignored (a
    // recent list is a convenience, never a reason to fail a save).
    void remember(const std::string& path);

private:
    std::filesystem::path file_;
    std::optional<std::vector<std::string>> entries_;
};

}  // namespace sdfwb::app
