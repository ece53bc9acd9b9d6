#pragma once
// The built-in file browser of the scene dialog and the image picker: a
// folder's subfolders and the files of the wanted kinds, listed when the
// folder changes (not every frame) and at most kMaxListedEntries of them, so
// a huge folder cannot stall the window; a path field to type in. The
// listing itself is a file-system service the app gives the panels
// (app/user_files/folder_listing.h).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sdfwb::ui {

inline constexpr std::size_t kMaxListedEntries = 5000;

struct FolderListing {
    std::vector<std::filesystem::path> folders;  // sorted by name
    std::vector<std::filesystem::path> files;    // sorted by name
    std::size_t omitted = 0;                     // entries past kMaxListedEntries, not listed
    std::string error;                           // why the folder cannot be read ("" when it can)
};

// Lists the subfolders of a folder and its files whose extension is one of
// `extensions` (lower case with the dot; matched ignoring case).
using FolderLister =
    std::function<FolderListing(const std::filesystem::path& folder, const std::vector<std::string>& extensions)>;

class FileBrowser {
public:
    explicit FileBrowser(std::vector<std::string> extensions) : extensions_(std::move(extensions)) {}

    // Shows `folder`, listed by `lister`, with `path` in the path field.
    void open(FolderLister lister, const std::filesystem::path& folder, const std::string& path);
    // Draws the listing, leaving `reserveBelow` pixels of the window under
    // it, then the path field; true when Enter was pressed in the field (on
    // a folder's path it shows that folder instead) or a file was
    // double-clicked: the caller accepts `path`.
    bool draw(float reserveBelow);

    std::string path;  // the text field: a file clicked in the listing, or typed

private:
    std::vector<std::string> extensions_;
    FolderLister lister_;
    std::filesystem::path folder_;
    FolderListing listing_;
};

}  // namespace sdfwb::ui
