#pragma once
// Where the command-line tools get a scene: a file, or the default scene
// embedded in the binary (so the program works from any directory).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::app {

// The text of scenes/default.json, embedded at build time.
std::string_view defaultSceneJson();

// "" or "default" gives the embedded default scene; otherwise the file.
// Throws scene::SceneError.
scene::Scene loadSceneArgument(const std::string& argument);

// Throws scene::SceneError, its problems prefixed with `source`, when a file
// the scene names cannot be read (an environment map's image); commands that
// render call it after loading, the editor shows these problems instead.
void requireSceneFiles(const scene::Scene& scene, const std::string& source);

// The .json files among `paths` in their order, each folder's searched
// recursively and sorted.
std::vector<std::filesystem::path> sceneFiles(const std::vector<std::string>& paths);

}  // namespace sdfwb::app
