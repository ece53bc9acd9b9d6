// Environment maps through both backends (program/scene_images.h and the
// shared sampler): a mirror ball in front of a box map reflects the face its
// reflected direction points at, the sky around it shows the face ahead, and
// the two backends agree. The faces are written by the test, one colour each.

#include <filesystem>

#include <gtest/gtest.h>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"
#include "gl_test_support.h"
#include "image/image_io.h"
#include "parity/parity.h"
#include "program/compile_scene.h"
#include "program/scene_images.h"
#include "support/scratch_folder.h"

namespace sdfwb {
namespace {

// +x -x +y -y +z -z: colours that survive the 8-bit files exactly
const glm::vec3 kFaceColours[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};

class EnvironmentMap : public test::GlTest {
protected:
    test::ScratchFolder folder{"sdfwb_environment_map_"};

    void SetUp() override {
        test::GlTest::SetUp();
        for (int face = 0; face < 6; ++face) {
            image::Image solid(8, 8);
            for (size_t i = 0; i < solid.pixelCount(); ++i) {
                for (int c = 0; c < 3; ++c) solid.rgb[3 * i + static_cast<size_t>(c)] = kFaceColours[face][c];
            }
            image::writeImage(folder / ("face" + std::to_string(face) + ".png"), solid);
        }
    }

    // A perfect mirror ball of radius 1 at the origin, the eye on +z looking
    // at it, no lights or ambient light: every colour comes from the map.
    scene::Scene mirrorBallInABox() const {
        scene::Scene s;
        s.directory.path = folder.path().string();
        s.camera = {.target = {0, 0, 0}, .azimuth = 0, .elevation = 0, .distance = 4, .fov = 50};
        s.lights.clear();
        s.environment.ambient = glm::dvec3(0);
        s.environment.map = scene::EnvironmentMapKind::Box;
        s.environment.boxPositiveX = "face0.png";
        s.environment.boxNegativeX = "face1.png";
        s.environment.boxPositiveY = "face2.png";
        s.environment.boxNegativeY = "face3.png";
        s.environment.boxPositiveZ = "face4.png";
        s.environment.boxNegativeZ = "face5.png";
        scene::Material mirror;
        mirror.name = "mirror";
        mirror.ambient = mirror.diffuse = mirror.specular = glm::dvec3(0);
        mirror.reflectivity = 1;
        s.materials.push_back(mirror);
        scene::Node ball = scene::Node::make(scene::NodeKind::Sphere);
        ball.set("radius", 1.0);
        ball.set("material", std::string("mirror"));
        s.root.children.push_back(ball);
        return s;
    }
};

glm::vec3 pixel(const image::Image& image, int x, int y) {
    const float* p =
        &image.rgb[3 * (static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x))];
    return {p[0], p[1], p[2]};
}

TEST_F(EnvironmentMap, AMirrorBallReflectsTheBoxFaceItsReflectionPointsAt) {
    scene::Scene s = mirrorBallInABox();
    EXPECT_TRUE(program::environmentProblems(s).empty());
    cpu::CpuBackend cpu;
    gl::GlBackend glBackend(context());
    parity::ParityResult r = parity::measureParity(s, cpu, glBackend, {.width = 64, .height = 64, .aa = 1});
    EXPECT_TRUE(r.passes);
    for (const image::Image* frame : {&r.cpuColor, &r.glColor}) {
        // the centre's ray comes straight back towards the eye: the +z face
        glm::vec3 centre = pixel(*frame, 32, 32);
        EXPECT_NEAR(centre.x, 1, 1e-3);
        EXPECT_NEAR(centre.y, 0, 1e-3);
        EXPECT_NEAR(centre.z, 1, 1e-3);
        // beside the ball the eye sees the -z face, ahead
        glm::vec3 sky = pixel(*frame, 1, 32);
        EXPECT_NEAR(sky.x, 0, 1e-3);
        EXPECT_NEAR(sky.y, 1, 1e-3);
        EXPECT_NEAR(sky.z, 1, 1e-3);
        // near the ball's top rim the reflection turns up: the +y face
        glm::vec3 top = pixel(*frame, 32, 32 - 14);
        EXPECT_NEAR(top.z, 1, 1e-3);
        EXPECT_NEAR(top.x, 0, 1e-3);
    }
}

TEST_F(EnvironmentMap, AMissingFaceIsNamedAndRendersAsThePlaceholder) {
    scene::Scene s = mirrorBallInABox();
    s.environment.boxNegativeY = "nowhere.png";
    std::vector<std::string> problems = program::environmentProblems(s);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("environment.box_ny: cannot read image ", 0), 0u) << problems[0];
    EXPECT_NE(problems[0].find("nowhere.png"), std::string::npos);
    cpu::CpuBackend cpu;
    gl::GlBackend glBackend(context());
    parity::ParityResult r = parity::measureParity(s, cpu, glBackend, {.width = 32, .height = 32, .aa = 1});
    EXPECT_TRUE(r.passes);
    EXPECT_EQ(r.cpuNonFinite, 0u);
}

}  // namespace
}  // namespace sdfwb
