#include "app/gui/camera_framing.h"

#include <cmath>

#include "program/bounds.h"

namespace sdfwb::app::gui {

scene::Camera framedCamera(const scene::Camera& camera, const scene::Node& node) {
    program::Bounds bounds = program::nodeBounds(node);
    if (bounds.empty || bounds.infinite) return camera;
    glm::dvec3 size = bounds.max - bounds.min;
    double radius = std::max(0.5 * std::sqrt(size.x * size.x + size.y * size.y + size.z * size.z), 1e-3);
    scene::Camera framed = camera;
    framed.target = 0.5 * (bounds.min + bounds.max);
    framed.distance = 1.15 * radius / std::sin(0.5 * camera.fov * 3.14159265358979323846 / 180.0);
    return framed;
}

}  // namespace sdfwb::app::gui
