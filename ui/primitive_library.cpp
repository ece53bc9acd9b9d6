#include "ui/primitive_library.h"

#include <algorithm>
#include <stdexcept>

#include "io/atomic_file.h"
#include "scene/scene_json.h"
#include "ui/user_paths.h"

namespace sdfwb::ui {
namespace {

std::filesystem::path folder() { return configDirectory() / "primitives"; }

std::filesystem::path fileOf(const std::string& name) {
    bool valid = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == ' ' || c == '-' || c == '_';
    });
    if (!valid) {
        throw std::runtime_error("library name \"" + name + "\": use letters, digits, spaces, '-' or '_'");
    }
    return folder() / (name + ".json");
}

}  // namespace

std::vector<std::string> libraryEntries() {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder(), error)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

void saveLibraryEntry(const std::string& name, const scene::Node& node) {
    std::filesystem::path file = fileOf(name);
    std::filesystem::create_directories(folder());
    io::writeTextAtomically(file, scene::nodeToJson(node).dump(2) + "\n");
}

scene::Node loadLibraryEntry(const std::string& name) {
    std::filesystem::path file = fileOf(name);
    std::string text = io::readTextFile(file);
    nlohmann::ordered_json json;
    try {
        json = nlohmann::ordered_json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        throw std::runtime_error(file.string() + ": invalid JSON: " + error.what());
    }
    return scene::nodeFromJson(json, file.string());
}

void removeLibraryEntry(const std::string& name) { std::filesystem::remove(fileOf(name)); }

}  // namespace sdfwb::ui
