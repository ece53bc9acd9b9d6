// Picking (issue 13, item 6): the pixel's ray is the renderer's own (same hit,
// same depth as the CPU image), and the primitive that decides the distance
// there is named by its node path: through transforms, booleans and smooth
// blends, for every shipped scene.

#include <algorithm>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "cpu/cpu_renderer.h"
#include "cpu/pick.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene_json.h"
#include "prune/prune_grid.h"
#include "support/large_scenes.h"
#include "support/scene_files.h"
#include "support/source_tree.h"

namespace sdfwb {
namespace {

using Path = std::vector<int>;

scene::Scene defaultScene() { return scene::loadSceneFile(sdfwb::test::sourceDir() + "/scenes/default.json"); }

// Image coordinates (pixels from the top left) where a world point appears.
glm::dvec2 project(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world) {
    scene::CameraFrame f = scene::cameraFrame(scene.camera);
    glm::dvec3 d = world - f.eye;
    double depth = glm::dot(d, f.forward);
    double u = glm::dot(d, f.right) / depth / f.tanHalfFov, v = glm::dot(d, f.up) / depth / f.tanHalfFov;
    double h = program.height, w = program.width;
    return {0.5 * (u * h + w), h - 0.5 * (v * h + h)};
}

cpu::PickResult pickAt(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world) {
    glm::dvec2 pixel = project(scene, program, world);
    return cpu::pickPixel(scene, program, pixel.x, pixel.y);
}

TEST(Pick, NamesThePrimitiveUnderThePixel) {
    scene::Scene scene = defaultScene();
    program::Program program = program::compileScene(scene, {.width = 320, .height = 180, .aa = 1});
    glm::dvec3 ballCentre(-0.9, 0.8, 0), boxCentre(1.1, 0.6, 0.2);
    cpu::PickResult ball = pickAt(scene, program, ballCentre);
    ASSERT_TRUE(ball.hit);
    EXPECT_EQ(ball.node, (Path{0, 0}));
    // the hit lies on the sphere, its normal points away from the centre
    EXPECT_NEAR(glm::length(ball.position - ballCentre), 0.8, 1e-2);
    EXPECT_GT(glm::dot(ball.normal, glm::normalize(ball.position - ballCentre)), 0.99);
    EXPECT_EQ(pickAt(scene, program, boxCentre).node, (Path{1, 0, 0}));
    // the floor is the ground, not a node; the sky is a miss
    cpu::PickResult floor = pickAt(scene, program, glm::dvec3(-3, 0, 2));
    ASSERT_TRUE(floor.hit);
    EXPECT_TRUE(floor.ground);
    EXPECT_EQ(floor.node, std::nullopt);
    EXPECT_NEAR(floor.position.y, 0, 0.05);  // within the pixel-footprint epsilon
    cpu::PickResult sky = cpu::pickPixel(scene, program, 160, 1);
    EXPECT_FALSE(sky.hit);
    EXPECT_EQ(sky.node, std::nullopt);
}

TEST(Pick, ACutSurfaceBelongsToTheCutterAndABlendToItsNearerSide) {
    scene::Scene scene = defaultScene();
    scene.environment.ground.enabled = false;
    scene::Node difference = scene::Node::make(scene::NodeKind::Difference);
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::dvec3(1.0));
    scene::Node cutter = scene::Node::make(scene::NodeKind::Sphere);
    cutter.set("radius", 0.6);
    scene::Node moved = scene::Node::make(scene::NodeKind::Translate);
    moved.set("offset", glm::dvec3(0, 0, 1.0));  // bites into the front face
    moved.children.push_back(cutter);
    difference.children = {box, moved};
    scene.root.children = {difference};
    scene.camera = {glm::dvec3(0), 0.0, 0.0, 6.0, 45.0};  // looking along -z at the front face
    program::Program program = program::compileScene(scene, {.width = 200, .height = 200, .aa = 1});
    EXPECT_EQ(cpu::pickPixel(scene, program, 100, 100).node, (Path{0, 1, 0}));  // inside the bite: the sphere
    EXPECT_EQ(pickAt(scene, program, glm::dvec3(0.8, 0.8, 1.0)).node, (Path{0, 0}));  // the face's corner: the box

    scene::Node blend = scene::Node::make(scene::NodeKind::SmoothUnion);
    scene::Node left = scene::Node::make(scene::NodeKind::Translate), right = left;
    left.set("offset", glm::dvec3(-0.6, 0, 0));
    right.set("offset", glm::dvec3(0.6, 0, 0));
    left.children = {scene::Node::make(scene::NodeKind::Sphere)};
    right.children = {scene::Node::make(scene::NodeKind::Sphere)};
    blend.children = {left, right};
    scene.root.children = {blend};
    program = program::compileScene(scene, {.width = 200, .height = 200, .aa = 1});
    EXPECT_EQ(pickAt(scene, program, glm::dvec3(-1.2, 0, 0.5)).node, (Path{0, 0, 0}));
    EXPECT_EQ(pickAt(scene, program, glm::dvec3(1.2, 0, 0.5)).node, (Path{0, 1, 0}));
}

class PickEveryScene : public ::testing::TestWithParam<test::SceneFile> {};

// The pick traces the renderer's ray: hit and depth agree with the CPU image
// pixel for pixel, and every hit names a primitive or the ground.
TEST_P(PickEveryScene, FollowsTheRenderersRayAndNamesAPrimitive) {
    scene::Scene scene = scene::loadSceneFile(GetParam().path());
    program::Program program = program::compileScene(scene, {.width = 24, .height = 16, .aa = 1});
    std::vector<Path> primitives = cpu::primitivePaths(scene.root);
    image::Frame frame = cpu::renderCpu(program).frame;
    for (int y = 0; y < program.height; y += 3) {
        for (int x = 0; x < program.width; x += 3) {
            cpu::PickResult pick = cpu::pickPixel(scene, program, x + 0.5, y + 0.5);
            size_t i = static_cast<size_t>(y * program.width + x);
            ASSERT_EQ(pick.hit, frame.coverage[i] > 0) << "pixel " << x << ", " << y;
            if (!pick.hit) continue;
            EXPECT_FLOAT_EQ(static_cast<float>(pick.t), frame.depth[i]) << "pixel " << x << ", " << y;
            if (!pick.ground) {
                ASSERT_TRUE(pick.node) << "pixel " << x << ", " << y;
                EXPECT_NE(std::find(primitives.begin(), primitives.end(), *pick.node), primitives.end());
            }
        }
    }
}

// A pick runs on the UI thread: it evaluates the whole program (the same
// floats as the pruned leaves) instead of building a grid, which takes
// seconds on a large scene.
TEST(Pick, LargeScenesPickWithoutBuildingAGrid) {
    scene::Scene scene = test::moleculeScene("molecule_100");
    program::Program program = program::compileScene(scene, {.width = 48, .height = 27, .aa = 1});
    long before = prune::pruneGridsBuilt();
    std::vector<cpu::PickResult> picks;
    for (int i = 0; i < program.width * program.height; ++i) {
        picks.push_back(cpu::pickPixel(scene, program, i % program.width + 0.5, i / program.width + 0.5));
    }
    auto hit = std::find_if(picks.begin(), picks.end(), [](const cpu::PickResult& p) { return p.hit; });
    ASSERT_NE(hit, picks.end());
    cpu::fieldDistance(scene, program, hit->position);
    cpu::fieldNormal(scene, program, hit->position);
    cpu::primitiveAt(scene, program, hit->position);
    EXPECT_EQ(prune::pruneGridsBuilt(), before);
    // and the picks see what the pruned render shows
    ASSERT_TRUE(prune::pruneGridFor(program));
    image::Frame frame = cpu::renderCpu(program).frame;
    for (size_t i = 0; i < picks.size(); ++i) {
        ASSERT_EQ(picks[i].hit, frame.coverage[i] > 0) << "pixel " << i;
        if (picks[i].hit) {
            EXPECT_EQ(static_cast<float>(picks[i].t), frame.depth[i]) << "pixel " << i;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PickEveryScene, ::testing::ValuesIn(test::allSceneFiles()),
                         [](const ::testing::TestParamInfo<test::SceneFile>& info) { return info.param.testName(); });

}  // namespace
}  // namespace sdfwb
