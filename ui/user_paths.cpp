#include "ui/user_paths.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "io/atomic_file.h"

namespace sdfwb::ui {
namespace {

std::filesystem::path xdg(const char* variable, const char* fallback) {
    const char* value = std::getenv(variable);
    if (value && *value) return std::filesystem::path(value) / "sdf-workbench";
    const char* home = std::getenv("HOME");
    return std::filesystem::path(home ? home : ".") / fallback / "sdf-workbench";
}

constexpr size_t kRecentFiles = 8;

}  // namespace

std::filesystem::path configDirectory() { return xdg("XDG_CONFIG_HOME", ".config"); }
std::filesystem::path stateDirectory() { return xdg("XDG_STATE_HOME", ".local/state"); }

std::vector<std::string> loadRecentFiles() {
    std::vector<std::string> files;
    std::ifstream in(configDirectory() / "recent.txt");
    for (std::string line; std::getline(in, line) && files.size() < kRecentFiles;) {
        // a file moved or deleted since leaves the list
        if (!line.empty() && std::filesystem::exists(line)) files.push_back(line);
    }
    return files;
}

void rememberRecentFile(const std::string& path) {
    std::vector<std::string> files = loadRecentFiles();
    std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    files.erase(std::remove(files.begin(), files.end(), absolute), files.end());
    files.insert(files.begin(), absolute);
    if (files.size() > kRecentFiles) files.resize(kRecentFiles);
    std::string text;
    for (const std::string& f : files) text += f + "\n";
    try {
        std::filesystem::create_directories(configDirectory());
        io::writeTextAtomically(configDirectory() / "recent.txt", text);
    } catch (const std::exception&) {
    }
}

}  // namespace sdfwb::ui
