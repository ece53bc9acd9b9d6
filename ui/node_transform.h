#pragma once
// Where a node sits in the world: the affine maps of translate, rotate and
// scale composed from the root down. Placement of new nodes and the move,
// rotate and scale handles convert between world and a node's frame here.
// Other operators (twist, bend, repetitions, ...) count as the identity: their
// frames are not affine, and the handles and placement treat them as fixed.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "ui/node_path.h"

namespace sdfwb::ui {

struct Affine {
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};

    glm::dvec3 apply(const glm::dvec3& p) const { return linear * p + offset; }
    // this after `inner`: (this * inner).apply(p) == apply(inner.apply(p))
    Affine operator*(const Affine& inner) const;
    Affine inverse() const;
};

// The node's own map from its children's frame to its parent's.
Affine ownTransform(const scene::Node& node);

// World from the frame of the children of the node at `path` (its own
// transform included); for a primitive, its shape's frame.
Affine worldFromInner(const scene::Node& root, const NodePath& path);

}  // namespace sdfwb::ui
