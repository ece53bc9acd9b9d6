#include "ui/node_transform.h"

#include <glm/matrix.hpp>

#include "program/rotation.h"

namespace sdfwb::ui {

Affine Affine::operator*(const Affine& inner) const { return {linear * inner.linear, linear * inner.offset + offset}; }

Affine Affine::inverse() const {
    glm::dmat3 back = glm::inverse(linear);
    return {back, -(back * offset)};
}

Affine ownTransform(const scene::Node& node) {
    switch (node.kind) {
    case scene::NodeKind::Translate: return {glm::dmat3(1.0), node.vec3("offset")};
    case scene::NodeKind::Rotate: return {program::rotationFromAngles(node.vec3("angles")), glm::dvec3(0.0)};
    case scene::NodeKind::Scale: return {glm::dmat3(node.real("factor")), glm::dvec3(0.0)};
    default: return {};
    }
}

Affine worldFromInner(const scene::Node& root, const NodePath& path) {
    const scene::Node* node = &root;
    Affine world = ownTransform(root);
    for (int index : path) {
        node = &node->children.at(static_cast<size_t>(index));
        world = world * ownTransform(*node);
    }
    return world;
}

}  // namespace sdfwb::ui
