#pragma once
// The surface of a scene as triangles: the scene's field (the CPU
// interpreter, in float as rendered) is sampled on a grid over the scene's
// bounds, near the surface only, into an OpenVDB grid, and OpenVDB's
// volume-to-mesh (dual contouring of the zero level set) makes the polygons.
// The ground plane is not part of the mesh; an unbounded scene (a plane, a
// formula without bounds) has no finite surface to mesh and is refused.
//
// Blocks of 8^3 voxels whose centre is farther from the surface than the
// block's half diagonal plus the narrow band are skipped without sampling
// their voxels: as for sphere tracing, the field must not overstate the
// distance to the surface.

#include <atomic>
#include <functional>
#include <stdexcept>

#include "mesh/mesh.h"
#include "scene/scene.h"

namespace sdfwb::mesh {

// Voxels along the longest side of the scene's bounds. The upper bound keeps
// the sampling (up to kMaxResolution^3 field evaluations) within minutes.
inline constexpr int kMinResolution = 8;
inline constexpr int kMaxResolution = 512;
inline constexpr int kDefaultResolution = 128;

struct MeshControl {
    const std::atomic<bool>* cancel = nullptr;      // set: stop soon, throw MeshCancelled
    std::function<void(double fraction)> progress;  // 0 to 1, from the calling thread
};

struct MeshCancelled : std::runtime_error {
    MeshCancelled() : std::runtime_error("mesh export cancelled") {}
};

// Throws std::invalid_argument "resolution must be 8 to 512 (got N)" or
// (extractMesh) std::runtime_error "the scene has no bounded surface to mesh ...".
void checkResolution(int resolution);
Mesh extractMesh(const scene::Scene& scene, int resolution, const MeshControl& control = {});

}  // namespace sdfwb::mesh
