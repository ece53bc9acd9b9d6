#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera_frame.h"

namespace sdfwb::scene {
namespace {

void expectOrthonormal(const CameraFrame& f) {
    for (const glm::dvec3& v : {f.forward, f.right, f.up}) {
        EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
    }
    EXPECT_NEAR(glm::dot(f.forward, f.right), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.forward, f.up), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.right, f.up), 0.0, 1e-12);
    glm::dvec3 back = glm::cross(f.right, f.up);
    EXPECT_NEAR(glm::distance(back, -f.forward), 0.0, 1e-12);
}

TEST(CameraFrame, LooksAtTheTargetFromTheOrbit) {
    Camera camera;
    camera.target = {1, 2, 3};
    camera.azimuth = 0;
    camera.elevation = 0;
    camera.distance = 5;
    CameraFrame f = cameraFrame(camera);
    EXPECT_NEAR(glm::distance(f.eye, glm::dvec3(1, 2, 8)), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(f.forward, glm::dvec3(0, 0, -1)), 0.0, 1e-12);
    expectOrthonormal(f);
}

TEST(CameraFrame, StraightDownAndUpStayValid) {
    for (double elevation : {90.0, -90.0, 89.999, -89.999}) {
        for (double azimuth : {0.0, 45.0, 180.0, -270.0}) {
            Camera camera;
            camera.elevation = elevation;
            camera.azimuth = azimuth;
            CameraFrame f = cameraFrame(camera);
            SCOPED_TRACE(elevation);
            expectOrthonormal(f);
            EXPECT_NEAR(glm::distance(camera.target - f.forward * camera.distance, f.eye), 0.0, 1e-12);
        }
    }
}

}  // namespace
}  // namespace sdfwb::scene
