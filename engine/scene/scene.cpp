#include "scene/scene.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sdfwb::scene {
namespace {

// NodeT is Node or const Node.
template <typename NodeT>
auto& fieldOf(NodeT& node, std::string_view field) {
    const KindSpec& spec = kindSpec(node.kind);
    int index = fieldIndex(spec, field);
    if (index < 0 || static_cast<size_t>(index) >= node.fields.size()) {
        throw std::logic_error("node kind " + std::string(spec.name) + " has no field " + std::string(field));
    }
    return node.fields[static_cast<size_t>(index)];
}

}  // namespace

Node Node::make(NodeKind kind) {
    Node node;
    node.kind = kind;
    for (const FieldSpec& field : kindSpec(kind).fields) {
        node.fields.push_back(field.defaultValue);
    }
    return node;
}

double Node::real(std::string_view field) const { return std::get<double>(fieldOf(*this, field)); }

glm::dvec3 Node::vec3(std::string_view field) const { return std::get<glm::dvec3>(fieldOf(*this, field)); }

const std::string& Node::text(std::string_view field) const {
    return std::get<std::string>(fieldOf(*this, field));
}

void Node::set(std::string_view field, FieldValue value) {
    fieldOf(*this, field) = std::move(value);
}

const Material* Scene::findMaterial(std::string_view name) const {
    for (const Material& m : materials) {
        if (m.name == name) {
            return &m;
        }
    }
    return nullptr;
}

bool Scene::hasMirrorsOrGlass() const {
    return std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.mirrorOrGlass(); });
}

Material defaultMaterial() {
    Material m;
    m.name = "";
    return m;
}

int treeDepth(const Node& node) {
    int deepest = 0;
    std::vector<std::pair<const Node*, int>> pending{{&node, 1}};
    while (!pending.empty()) {
        auto [current, depth] = pending.back();
        pending.pop_back();
        deepest = std::max(deepest, depth);
        for (const Node& child : current->children) pending.emplace_back(&child, depth + 1);
    }
    return deepest;
}

}  // namespace sdfwb::scene
