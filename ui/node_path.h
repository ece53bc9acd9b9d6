#pragma once
// Addressing nodes of the scene tree by their JSON path, as the loader's
// messages and the script language spell them: "root", "root.children[0]",
// "root.children[1].children[0]".

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::ui {

// Child indices from the root; empty is the root itself.
using NodePath = std::vector<int>;

std::string formatNodePath(const NodePath& path);

// The path, or nullopt when `text` is not of the form root(.children[N])*.
std::optional<NodePath> parseNodePath(std::string_view text);

// The steps of any JSON path of the scene file: "lights[0].softness" is the
// key lights, the index 0, the key softness. False on bad syntax.
struct JsonStep {
    std::string key;  // empty for an index step
    int index = -1;
};
bool splitJsonPath(std::string_view text, std::vector<JsonStep>& steps);

// nullptr when the path leads nowhere in `root`.
const scene::Node* findNode(const scene::Node& root, const NodePath& path);
scene::Node* findNode(scene::Node& root, const NodePath& path);

// Whether the node at `path` draws (scene/visibility.h): it and every node
// above it are neither hidden nor left out by a solo. False when the path
// leads nowhere.
bool drawsAt(const scene::Node& root, const NodePath& path);

// Whether `inner` is `outer` or lies inside its subtree.
bool isWithin(const NodePath& inner, const NodePath& outer);

// The parent's path; the root has none (checked by the caller: path non-empty).
NodePath parentOf(const NodePath& path);

}  // namespace sdfwb::ui
