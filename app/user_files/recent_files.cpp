#include "app/user_files/recent_files.h"

#include <algorithm>
#include <fstream>

#include "app/user_files/user_paths.h"
#include "io/atomic_file.h"

namespace sdfwb::app {
namespace {

constexpr std::size_t kRecentFiles = 8;

}  // namespace

RecentFiles::RecentFiles() : RecentFiles(configDirectory() / "recent.txt") {}

RecentFiles::RecentFiles(std::filesystem::path file) : file_(std::move(file)) {}

const std::vector<std::string>& RecentFiles::entries() {
    if (!entries_) refresh();
    return *entries_;
}

void RecentFiles::refresh() {
    std::vector<std::string> files;
    std::ifstream in(file_);
    for (std::string line; std::getline(in, line) && files.size() < kRecentFiles;) {
        // a file moved or deleted since leaves the list
        std::error_code error;
        if (!line.empty() && std::filesystem::exists(line, error)) files.push_back(line);
    }
    entries_ = std::move(files);
}

void RecentFiles::remember(const std::string& path) {
    refresh();
    std::vector<std::string>& files = *entries_;
    std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    files.erase(std::remove(files.begin(), files.end(), absolute), files.end());
    files.insert(files.begin(), absolute);
    if (files.size() > kRecentFiles) files.resize(kRecentFiles);
    std::string text;
    for (const std::string& f : files) text += f + "\n";
    try {
        std::filesystem::create_directories(file_.parent_path());
        io::writeTextAtomically(file_, text);
    } catch (const std::exception&) {}
}

}  // namespace sdfwb::app
