#include "scene/camera_frame.h"

#include <cmath>

#include <glm/trigonometric.hpp>

namespace sdfwb::scene {

CameraFrame cameraFrame(const Camera& camera) {
    double a = glm::radians(camera.azimuth);
    double e = glm::radians(camera.elevation);
    double ca = std::cos(a), sa = std::sin(a), ce = std::cos(e), se = std::sin(e);
    glm::dvec3 backward(ce * sa, se, ce * ca);
    CameraFrame frame;
    frame.eye = camera.target + backward * camera.distance;
    frame.forward = -backward;
    frame.right = glm::dvec3(ca, 0.0, -sa);
    frame.up = glm::dvec3(-se * sa, ce, -se * ca);
    frame.tanHalfFov = std::tan(glm::radians(camera.fov) * 0.5);
    return frame;
}

}  // namespace sdfwb::scene
