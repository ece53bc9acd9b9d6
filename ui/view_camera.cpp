#include "ui/view_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include "scene/camera_frame.h"

namespace sdfwb::ui {
namespace {

constexpr double kMaxElevation = 89.0;  // degrees: the frame stays valid at 90, the orbit feels stuck there
// The eye stays this fraction of its distance above the ground, so the ground
// never fills the view edge-on.
constexpr double kGroundMargin = 0.02;

}  // namespace

scene::Camera framedCamera(const scene::Camera& camera, const scene::Node& node) {
    program::Bounds bounds = program::nodeBounds(node);
    if (bounds.empty || bounds.infinite) return camera;
    glm::dvec3 size = bounds.max - bounds.min;
    double radius = std::max(0.5 * std::sqrt(size.x * size.x + size.y * size.y + size.z * size.z), 1e-3);
    scene::Camera framed = camera;
    framed.target = 0.5 * (bounds.min + bounds.max);
    framed.distance = 1.15 * radius / std::sin(0.5 * glm::radians(camera.fov));
    return framed;
}

program::Bounds worldBounds(const scene::Node& root, const NodePath& path) {
    const scene::Node* node = findNode(root, path);
    if (!node) return {};
    // the ancestors down to the node, each holding only the child on the path:
    // their bounds rules then carry the node's bounds into world space
    scene::Node chain = *node;
    for (size_t depth = path.size(); depth-- > 0;) {
        const scene::Node* ancestor = findNode(root, NodePath(path.begin(), path.begin() + static_cast<long>(depth)));
        scene::Node holder;
        holder.kind = ancestor->kind;
        holder.fields = ancestor->fields;
        holder.children.push_back(std::move(chain));
        chain = std::move(holder);
    }
    return program::nodeBounds(chain);
}

scene::Camera frameAllCamera(const scene::Scene& scene) {
    scene::Camera home = scene.camera;
    home.azimuth = kHomeAzimuth;
    home.elevation = kHomeElevation;
    return framedCamera(home, scene.root);
}

std::optional<scene::Camera> frameSelectedCamera(const scene::Scene& scene, const NodePath& path) {
    program::Bounds bounds = worldBounds(scene.root, path);
    if (bounds.empty || bounds.infinite) return std::nullopt;
    scene::Node box = scene::Node::make(scene::NodeKind::Box);
    box.set("half_extents", glm::max(0.5 * (bounds.max - bounds.min), glm::dvec3(1e-3)));
    scene::Camera framed = framedCamera(scene.camera, box);
    framed.target = 0.5 * (bounds.min + bounds.max);
    return framed;
}

double lowestElevation(const scene::Camera& camera, const scene::Environment& environment) {
    if (!environment.ground.enabled) return -kMaxElevation;
    double above = (environment.ground.height - camera.target.y) / camera.distance + kGroundMargin;
    double lowest = glm::degrees(std::asin(std::clamp(above, -1.0, 1.0)));
    return std::clamp(lowest, -kMaxElevation, kMaxElevation);
}

bool eyeBelowGround(const scene::Camera& camera, const scene::Environment& environment) {
    return environment.ground.enabled && scene::cameraFrame(camera).eye.y <= environment.ground.height;
}

scene::Camera orbited(const scene::Camera& camera, const scene::Environment& environment, double azimuthStep,
                      double elevationStep) {
    scene::Camera c = camera;
    c.azimuth = std::remainder(c.azimuth + azimuthStep, 360.0);
    c.elevation = std::clamp(c.elevation + elevationStep, lowestElevation(c, environment), kMaxElevation);
    return c;
}

scene::Camera panned(const scene::Camera& camera, double dx, double dy, double viewHeight) {
    scene::Camera c = camera;
    scene::CameraFrame frame = scene::cameraFrame(c);
    double perPixel = 2.0 * c.distance * frame.tanHalfFov / std::max(1.0, viewHeight);
    c.target += (-dx * perPixel) * frame.right + (dy * perPixel) * frame.up;
    return c;
}

scene::Camera zoomed(const scene::Camera& camera, const scene::Environment& environment, double notches) {
    scene::Camera c = camera;
    c.distance = std::clamp(c.distance * std::pow(0.9, notches), 1e-3, 1e6);
    // farther out along a downward view can sink the eye: lift it back
    c.elevation = std::max(c.elevation, std::min(lowestElevation(c, environment), kMaxElevation));
    return c;
}

scene::Camera presetCamera(const scene::Camera& camera, ViewPreset preset) {
    scene::Camera c = camera;
    switch (preset) {
    case ViewPreset::Front: c.azimuth = 0; c.elevation = 0; break;
    case ViewPreset::Back: c.azimuth = 180; c.elevation = 0; break;
    case ViewPreset::Right: c.azimuth = 90; c.elevation = 0; break;
    case ViewPreset::Left: c.azimuth = -90; c.elevation = 0; break;
    case ViewPreset::Top: c.azimuth = 0; c.elevation = 90; break;
    case ViewPreset::Bottom: c.azimuth = 0; c.elevation = -90; break;
    }
    return c;
}

std::optional<ViewPreset> viewPresetNamed(std::string_view name) {
    constexpr std::pair<std::string_view, ViewPreset> kNames[] = {
        {"front", ViewPreset::Front}, {"back", ViewPreset::Back}, {"right", ViewPreset::Right},
        {"left", ViewPreset::Left},   {"top", ViewPreset::Top},   {"bottom", ViewPreset::Bottom}};
    for (const auto& [word, preset] : kNames) {
        if (word == name) return preset;
    }
    return std::nullopt;
}

}  // namespace sdfwb::ui
