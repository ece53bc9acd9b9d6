#pragma once
// Folder listings for the built-in file browser (ui/file_browser.h): the
// file-system service behind the scene dialog and the image picker.

#include <filesystem>
#include <string>
#include <vector>

#include "ui/file_browser.h"

namespace sdfwb::app {

// The subfolders of `folder` and its files whose extension is one of
// `extensions` (lower case with the dot; matched ignoring case), sorted by
// name, at most ui::kMaxListedEntries entries (the rest counted).
ui::FolderListing listFolder(const std::filesystem::path& folder, const std::vector<std::string>& extensions);

}  // namespace sdfwb::app
