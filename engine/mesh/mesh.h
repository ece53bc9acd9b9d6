#pragma once
// A triangle mesh of a scene's surface (mesh/extract_mesh.h) as the mesh
// files hold it (mesh/mesh_files.h).

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace sdfwb::mesh {

struct Mesh {
    std::vector<glm::vec3> vertices;  // world coordinates
    // Indices into `vertices`, counter-clockwise seen from outside (the
    // normal points out of the solid).
    std::vector<glm::u32vec3> triangles;
    double voxelSize = 0;  // of the grid the surface was extracted from
};

}  // namespace sdfwb::mesh
