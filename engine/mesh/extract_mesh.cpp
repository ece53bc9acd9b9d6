#include "mesh/extract_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include "cpu/interpreter.h"
#include "jobs/parallel_for.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"

namespace sdfwb::mesh {
namespace {

constexpr int kBlock = 8;      // voxels per block side: one skip decision each
constexpr double kBand = 3.0;  // active voxels lie within this many voxels of the surface
constexpr int kPadding = 4;    // voxels around the bounds, so the surface closes inside the grid

struct GridShape {
    glm::dvec3 origin;  // march coordinates of voxel (0, 0, 0)
    double h = 0;       // voxel size
    glm::ivec3 voxels;  // per axis
    glm::ivec3 blocks;  // per axis
};

GridShape gridShape(const program::Program& program, int resolution) {
    glm::dvec3 extent = program.rootMax - program.rootMin;
    double longest = std::max({extent.x, extent.y, extent.z, 1e-9});
    GridShape g;
    g.h = longest / resolution;
    for (int a = 0; a < 3; ++a) {
        g.voxels[a] = static_cast<int>(std::ceil(extent[a] / g.h)) + 1 + 2 * kPadding;
        g.blocks[a] = (g.voxels[a] + kBlock - 1) / kBlock;
    }
    g.origin = program.rootMin - glm::dvec3(kPadding * g.h);
    return g;
}

// One block's samples, or nothing when the block is wholly far from the surface.
struct BlockSamples {
    bool sampled = false;
    float values[kBlock * kBlock * kBlock];
};

}  // namespace

void checkResolution(int resolution) {
    if (resolution < kMinResolution || resolution > kMaxResolution) {
        throw std::invalid_argument("resolution must be " + std::to_string(kMinResolution) + " to " +
                                    std::to_string(kMaxResolution) + " (got " + std::to_string(resolution) + ")");
    }
}

Mesh extractMesh(const scene::Scene& scene, int resolution, const MeshControl& control) {
    checkResolution(resolution);
    scene::Scene solid = scene;
    solid.environment.ground.enabled = false;  // the floor is the renderer's, not the model's
    program::Program program = program::compileScene(solid, {.width = 2, .height = 2, .aa = 1, .prune = false});
    if (!program.rootBounded) {
        throw std::runtime_error(
            "the scene has no bounded surface to mesh (it is empty, or a plane or a formula without bounds reaches "
            "infinity)");
    }
    const GridShape g = gridShape(program, resolution);
    const cpu::f32::Kernel kernel(program);
    const float band = static_cast<float>(kBand * g.h);
    // Lipschitz: no voxel of a block is within the band when the centre is this far
    const double skipBeyond = (std::sqrt(3.0) * 0.5 * kBlock + kBand + 1.0) * g.h;

    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(band);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(g.h));
    grid->transform().postTranslate(openvdb::Vec3d(g.origin.x, g.origin.y, g.origin.z));
    openvdb::FloatGrid::Accessor access = grid->getAccessor();

    const int slabBlocks = g.blocks.x * g.blocks.y;
    std::vector<BlockSamples> slab(static_cast<size_t>(slabBlocks));
    for (int bz = 0; bz < g.blocks.z; ++bz) {
        if (control.cancel && control.cancel->load()) throw MeshCancelled();
        jobs::parallelFor(slabBlocks, [&](int index) {
            const glm::ivec3 base(index % g.blocks.x * kBlock, index / g.blocks.x * kBlock, bz * kBlock);
            cpu::f32::Scratch scratch(program);
            auto field = [&](glm::dvec3 p) { return static_cast<float>(kernel.map(scratch, cpu::f32::vec3(p)).d); };
            BlockSamples& out = slab[static_cast<size_t>(index)];
            const glm::dvec3 centre = g.origin + (glm::dvec3(base) + 0.5 * (kBlock - 1)) * g.h;
            out.sampled = !(std::abs(field(centre)) > skipBeyond);  // a NaN centre is sampled
            if (!out.sampled) return;
            int i = 0;
            for (int z = 0; z < kBlock; ++z)
                for (int y = 0; y < kBlock; ++y)
                    for (int x = 0; x < kBlock; ++x)
                        out.values[i++] = field(g.origin + glm::dvec3(base + glm::ivec3(x, y, z)) * g.h);
        });
        for (int index = 0; index < slabBlocks; ++index) {
            const BlockSamples& block = slab[static_cast<size_t>(index)];
            if (!block.sampled) continue;
            const glm::ivec3 base(index % g.blocks.x * kBlock, index / g.blocks.x * kBlock, bz * kBlock);
            int i = 0;
            for (int z = 0; z < kBlock; ++z)
                for (int y = 0; y < kBlock; ++y)
                    for (int x = 0; x < kBlock; ++x) {
                        float d = block.values[i++];
                        openvdb::Coord at(base.x + x, base.y + y, base.z + z);
                        if (!std::isfinite(d)) continue;  // undefined field: left to the background
                        if (std::abs(d) < band) {
                            access.setValueOn(at, d);
                        } else {
                            access.setValueOff(at, d < 0 ? -band : band);
                        }
                    }
        }
        if (control.progress) control.progress(0.9 * (bz + 1) / g.blocks.z);
    }
    if (control.cancel && control.cancel->load()) throw MeshCancelled();

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0);

    Mesh mesh;
    mesh.voxelSize = g.h;
    const glm::dvec3 eye = scene::cameraFrame(scene.camera).eye;  // march coordinates are world minus the eye
    mesh.vertices.reserve(points.size());
    for (const openvdb::Vec3s& p : points) {
        mesh.vertices.emplace_back(glm::dvec3(p.x(), p.y(), p.z()) + eye);
    }
    // OpenVDB winds its polygons counter-clockwise seen from the positive side (outside)
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    for (const openvdb::Vec3I& t : triangles) mesh.triangles.emplace_back(t[0], t[1], t[2]);
    for (const openvdb::Vec4I& q : quads) {
        mesh.triangles.emplace_back(q[0], q[1], q[2]);
        mesh.triangles.emplace_back(q[0], q[2], q[3]);
    }
    if (control.progress) control.progress(1.0);
    return mesh;
}

}  // namespace sdfwb::mesh
