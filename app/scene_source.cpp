#include "app/scene_source.h"

#include <algorithm>
#include <filesystem>

#include "program/scene_images.h"
#include "scene/scene_json.h"

namespace sdfwb::app {

scene::Scene loadSceneArgument(const std::string& argument) {
    if (argument.empty() || (argument == "default" && !std::filesystem::exists(argument))) {
        return scene::parseScene(defaultSceneJson());
    }
    return scene::loadSceneFile(argument);
}

void requireSceneFiles(const scene::Scene& scene, const std::string& source) {
    std::vector<std::string> problems = program::sceneImageProblems(scene);
    if (problems.empty()) return;
    for (std::string& problem : problems) problem = (source.empty() ? "default" : source) + ": " + problem;
    throw scene::SceneError(problems);
}

std::vector<std::filesystem::path> sceneFiles(const std::vector<std::string>& paths) {
    std::vector<std::filesystem::path> files;
    for (const std::string& path : paths) {
        if (std::filesystem::is_directory(path)) {
            std::vector<std::filesystem::path> found;
            for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
                if (entry.is_regular_file() && entry.path().extension() == ".json") found.push_back(entry.path());
            }
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else {
            files.emplace_back(path);
        }
    }
    return files;
}

}  // namespace sdfwb::app
