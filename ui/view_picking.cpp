#include "ui/view_picking.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {

cpu::PickResult pickView(const scene::Scene& scene, int width, int height, double x, double y) {
    program::Program program = program::compileScene(scene, {std::max(width, 1), std::max(height, 1), 1});
    return cpu::pickPixel(scene, program, x, y);
}

void selectPicked(Editor& editor, const cpu::PickResult& pick) {
    editor.select(pick.node ? std::optional<NodePath>(*pick.node) : std::nullopt);
}

std::optional<glm::dvec2> projectToView(const scene::Scene& scene, const glm::dvec3& world, int width, int height) {
    scene::CameraFrame f = scene::cameraFrame(scene.camera);
    glm::dvec3 d = world - f.eye;
    double depth = glm::dot(d, f.forward);
    if (depth <= 1e-6) return std::nullopt;
    // cameraRay's mapping inverted: u = (2 px - w) / h * tan, v likewise, rows from the top
    double u = glm::dot(d, f.right) / depth / f.tanHalfFov, v = glm::dot(d, f.up) / depth / f.tanHalfFov;
    return glm::dvec2(0.5 * (u * height + width), height - 0.5 * (v * height + height));
}

ViewRay viewRay(const scene::Scene& scene, int width, int height, const glm::dvec2& point) {
    scene::CameraFrame f = scene::cameraFrame(scene.camera);
    double u = (2.0 * point.x - width) / height * f.tanHalfFov, v = (height - 2.0 * point.y) / height * f.tanHalfFov;
    return {f.eye, glm::normalize(f.forward + u * f.right + v * f.up)};
}

std::optional<ImageRect> outlineRect(const scene::Scene& scene, const NodePath& path, int width, int height) {
    if (!drawsAt(scene.root, path)) return std::nullopt;  // nothing drawn to outline
    program::Bounds b = worldBounds(scene.root, path);
    if (b.empty || b.infinite) return std::nullopt;
    std::optional<ImageRect> rect;
    for (int corner = 0; corner < 8; ++corner) {
        std::optional<glm::dvec2> at = projectToView(scene, b.corner(corner), width, height);
        if (!at) return std::nullopt;  // around the eye: no honest rectangle
        if (!rect) rect = ImageRect{*at, *at};
        rect->min = glm::min(rect->min, *at);
        rect->max = glm::max(rect->max, *at);
    }
    return rect;
}

}  // namespace sdfwb::ui
