#include "app/user_files/primitive_folder.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "app/user_files/user_paths.h"
#include "io/atomic_file.h"
#include "scene/scene_json.h"

namespace sdfwb::app {

PrimitiveFolder::PrimitiveFolder() : PrimitiveFolder(configDirectory() / "primitives") {}

PrimitiveFolder::PrimitiveFolder(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path PrimitiveFolder::fileOf(const std::string& name) const {
    bool valid = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == ' ' || c == '-' || c == '_';
    });
    if (!valid) {
        throw std::runtime_error("library name \"" + name + "\": use letters, digits, spaces, '-' or '_'");
    }
    return folder_ / (name + ".json");
}

const std::vector<std::string>& PrimitiveFolder::entries() {
    if (!entries_) refresh();
    return *entries_;
}

void PrimitiveFolder::refresh() {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    entries_ = std::move(names);
}

void PrimitiveFolder::save(const std::string& name, const scene::Node& node) {
    std::filesystem::path file = fileOf(name);
    std::filesystem::create_directories(folder_);
    io::writeTextAtomically(file, scene::nodeToJson(node).dump(2) + "\n");
    refresh();
}

scene::Node PrimitiveFolder::load(const std::string& name) const {
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

void PrimitiveFolder::remove(const std::string& name) {
    std::filesystem::path file = fileOf(name);
    std::string text = io::readTextFile(file);
    std::error_code error;
    if (!std::filesystem::remove(file, error) || error) {
        throw std::runtime_error("cannot remove " + file.string() + (error ? ": " + error.message() : ""));
    }
    removedName_ = name;
    removedText_ = std::move(text);
    refresh();
}

void PrimitiveFolder::restoreRemoved() {
    if (!removedName_) return;
    std::filesystem::create_directories(folder_);
    io::writeTextAtomically(fileOf(*removedName_), removedText_);
    removedName_.reset();
    removedText_.clear();
    refresh();
}

}  // namespace sdfwb::app
