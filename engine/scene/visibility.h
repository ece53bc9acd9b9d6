#pragma once
// Hide and solo (docs/scene-format.md): which nodes of a tree draw.
//
// A hidden node draws nothing: it counts as empty space, as an empty union
// does (in a union it is gone, as a difference's cutter it cuts nothing).
// While any node of the tree is soloed, only soloed subtrees draw, with the
// operators above them; their other children count as empty space. The
// compiler, the pick and the bounds ask here, so every layer agrees on what
// a hidden node is.

#include <unordered_set>

#include "scene/scene.h"

namespace sdfwb::scene {

class Visibility {
public:
    explicit Visibility(const Node& root);

    // Whether `node` (in the tree given to the constructor, reached from a
    // drawn parent) draws.
    bool draws(const Node& node) const;

private:
    bool anySolo_ = false;
    std::unordered_set<const Node*> shownBySolo_;  // soloed subtrees and their ancestors
};

}  // namespace sdfwb::scene
