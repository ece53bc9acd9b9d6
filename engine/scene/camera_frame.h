#pragma once
// The orbit camera's world-space frame, built from the angles directly so that
// elevation +-90 degrees (looking straight down or up) gives a valid frame.

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace sdfwb::scene {

struct CameraFrame {
    glm::dvec3 eye;
    glm::dvec3 forward;  // unit, from eye to target
    glm::dvec3 right;    // unit
    glm::dvec3 up;       // unit; right x up = -forward
    double tanHalfFov;
};

CameraFrame cameraFrame(const Camera& camera);

}  // namespace sdfwb::scene
