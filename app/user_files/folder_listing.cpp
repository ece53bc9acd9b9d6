#include "app/user_files/folder_listing.h"

#include <algorithm>
#include <cctype>

namespace sdfwb::app {
namespace fs = std::filesystem;

namespace {

std::string lowerCase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace

ui::FolderListing listFolder(const fs::path& folder, const std::vector<std::string>& extensions) {
    ui::FolderListing listing;
    std::error_code error;
    fs::directory_iterator entries(folder, error);
    if (error) {
        listing.error = "cannot list " + folder.string() + ": " + error.message();
        return listing;
    }
    std::size_t seen = 0;
    for (const fs::directory_entry& entry : entries) {
        if (++seen > ui::kMaxListedEntries) {
            ++listing.omitted;
            continue;
        }
        std::error_code typeError;  // a dangling link or a vanished file is simply not listed
        if (entry.is_directory(typeError)) {
            listing.folders.push_back(entry.path());
        } else if (entry.is_regular_file(typeError)) {
            std::string extension = lowerCase(entry.path().extension().string());
            if (std::find(extensions.begin(), extensions.end(), extension) != extensions.end())
                listing.files.push_back(entry.path());
        }
    }
    auto byName = [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); };
    std::sort(listing.folders.begin(), listing.folders.end(), byName);
    std::sort(listing.files.begin(), listing.files.end(), byName);
    return listing;
}

}  // namespace sdfwb::app
