#include "scene/scene.h"

#include <stdexcept>

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

Material defaultMaterial() {
    Material m;
    m.name = "";
    return m;
}

}  // namespace sdfwb::scene
