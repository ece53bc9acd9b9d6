#pragma once
// Reading and writing scenes as JSON (docs/scene-format.md).
// Reading validates everything and reports every problem with its JSON path,
// e.g. "root.children[2].radius: must be > 0 (got -1)"; unknown fields are errors.
// Writing is canonical: fixed key order, every field present, byte-stable.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace sdfwb::scene {

class SceneError : public std::runtime_error {
public:
    explicit SceneError(std::vector<std::string> problems);
    // Each problem is one line: "<json path>: <reason>" or "line L, column C: <reason>".
    const std::vector<std::string>& problems() const { return problems_; }

private:
    std::vector<std::string> problems_;
};

// Throws SceneError.
Scene parseScene(std::string_view jsonText);
Scene sceneFromJson(const nlohmann::ordered_json& json);
// Scene files larger than this are refused before they are read (the parsed
// document takes several times the file's size in memory).
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t(64) << 20;

// Throws SceneError whose problems start with the file name.
Scene loadSceneFile(const std::filesystem::path& path);

nlohmann::ordered_json sceneToJson(const Scene& scene);
std::string serializeScene(const Scene& scene);
// Writes a temporary file next to `path` and renames it over `path`; throws
// std::runtime_error naming the path on failure (also for a tree deeper than
// kMaxNodeDepth, which could not be loaded again) and leaves no partial file.
void saveSceneFile(const Scene& scene, const std::filesystem::path& path);

// Node-level conversion, used by the editor's clipboard and primitive library.
nlohmann::ordered_json nodeToJson(const Node& node);
// `path` prefixes problem messages (e.g. "root.children[0]"). Throws SceneError.
Node nodeFromJson(const nlohmann::ordered_json& json, const std::string& path);

}  // namespace sdfwb::scene
