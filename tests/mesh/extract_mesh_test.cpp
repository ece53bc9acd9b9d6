// Meshes of a scene's surface (issue 13) checked against the field: every
// vertex lies within a voxel of the surface, a solid's mesh is a closed
// manifold wound outwards enclosing the solid's volume, and bad requests are
// refused before any sampling.

#include <atomic>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "support/source_tree.h"

#include "cpu/pick.h"
#include "mesh/extract_mesh.h"
#include "mesh_checks.h"
#include "program/compile_scene.h"
#include "scene/scene_json.h"

namespace sdfwb::mesh {
namespace {

scene::Scene sphereScene(double radius, glm::dvec3 centre = glm::dvec3(0.0)) {
    scene::Scene s;
    scene::Node ball = scene::Node::make(scene::NodeKind::Sphere);
    ball.set("radius", radius);
    scene::Node at = scene::Node::make(scene::NodeKind::Translate);
    at.set("offset", centre);
    at.children.push_back(ball);
    s.root.children.push_back(at);
    return s;
}

// The largest |field| at the mesh's vertices (the field as rendered, the ground left out).
double worstVertexDistance(const scene::Scene& scene, const Mesh& mesh) {
    scene::Scene solid = scene;
    solid.environment.ground.enabled = false;
    program::Program program = program::compileScene(solid, {.width = 2, .height = 2, .aa = 1, .prune = false});
    double worst = 0;
    for (const glm::vec3& v : mesh.vertices) {
        worst = std::max(worst, std::abs(cpu::fieldDistance(solid, program, glm::dvec3(v))));
    }
    return worst;
}

TEST(ExtractMesh, ASphereIsAClosedManifoldOnItsSurface) {
    const double r = 0.8;
    scene::Scene scene = sphereScene(r, {0.3, 1.0, -0.2});
    Mesh mesh = extractMesh(scene, 48);
    ASSERT_GT(mesh.triangles.size(), 1000u);
    EXPECT_NEAR(mesh.voxelSize, 2 * r / 48, 0.1 * 2 * r / 48);  // the bounds are the sphere's, maybe padded
    EXPECT_LE(worstVertexDistance(scene, mesh), mesh.voxelSize);
    std::size_t edges = 0;
    ASSERT_TRUE(closedManifold(mesh, &edges));
    // a sphere's surface: Euler characteristic 2
    EXPECT_EQ(
        static_cast<long>(mesh.vertices.size()) - static_cast<long>(edges) + static_cast<long>(mesh.triangles.size()),
        2);
    double exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    EXPECT_NEAR(signedVolume(mesh), exact, 0.02 * exact);  // positive: wound outwards
}

TEST(ExtractMesh, TheDefaultSceneLeavesTheGroundOutAndClosesEverySolid) {
    scene::Scene scene = scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json");
    Mesh mesh = extractMesh(scene, 64);
    ASSERT_GT(mesh.triangles.size(), 1000u);
    EXPECT_LE(worstVertexDistance(scene, mesh), mesh.voxelSize);
    EXPECT_TRUE(closedManifold(mesh));
    EXPECT_GT(signedVolume(mesh), 0);
    for (const glm::vec3& v : mesh.vertices) ASSERT_GT(v.y, scene.environment.ground.height - 1.0f);  // no floor
}

TEST(ExtractMesh, RefusesBadResolutionsAndUnboundedScenes) {
    scene::Scene ball = sphereScene(1);
    EXPECT_THROW(extractMesh(ball, kMinResolution - 1), std::invalid_argument);
    EXPECT_THROW(extractMesh(ball, kMaxResolution + 1), std::invalid_argument);
    try {
        checkResolution(100000);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "resolution must be 8 to 512 (got 100000)");
    }
    scene::Scene plane;
    plane.root.children.push_back(scene::Node::make(scene::NodeKind::Plane));
    EXPECT_THROW(extractMesh(plane, 32), std::runtime_error);
    EXPECT_THROW(extractMesh(scene::Scene{}, 32), std::runtime_error);  // nothing at all
}

TEST(ExtractMesh, ACancelStopsIt) {
    std::atomic<bool> cancel{false};
    int reports = 0;
    MeshControl control{&cancel, [&](double fraction) {
                            EXPECT_GE(fraction, 0.0);
                            EXPECT_LE(fraction, 1.0);
                            if (++reports == 2) cancel = true;
                        }};
    EXPECT_THROW(extractMesh(sphereScene(1), 64, control), MeshCancelled);
    EXPECT_EQ(reports, 2);
}

}  // namespace
}  // namespace sdfwb::mesh
