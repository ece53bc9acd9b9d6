#pragma once
// What a mesh of a solid must be, for the mesh tests.

#include <cstddef>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "mesh/mesh.h"

namespace sdfwb::mesh {

// Closed and consistently oriented: every edge is used by exactly two
// triangles, once in each direction, and no triangle repeats a vertex.
inline bool closedManifold(const Mesh& mesh, std::size_t* edges = nullptr) {
    std::map<std::pair<unsigned, unsigned>, int> directed;
    for (const glm::u32vec3& t : mesh.triangles) {
        if (t.x == t.y || t.y == t.z || t.x == t.z) return false;
        for (auto [a, b] : {std::pair{t.x, t.y}, std::pair{t.y, t.z}, std::pair{t.z, t.x}}) {
            if (++directed[{a, b}] > 1) return false;
        }
    }
    for (const auto& [edge, count] : directed) {
        if (!directed.count({edge.second, edge.first})) return false;
    }
    if (edges) *edges = directed.size() / 2;
    return true;
}

// The enclosed volume (divergence theorem); positive when the triangles wind
// counter-clockwise seen from outside.
inline double signedVolume(const Mesh& mesh) {
    double volume = 0;
    for (const glm::u32vec3& t : mesh.triangles) {
        glm::dvec3 a(mesh.vertices[t.x]), b(mesh.vertices[t.y]), c(mesh.vertices[t.z]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

}  // namespace sdfwb::mesh
