#include "program/texture_mapping.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "sdf/shared.h"

namespace sdfwb::program {
namespace {

namespace shared = sdf::f64;
using glm::dvec3;
using glm::dvec4;

double smallest(dvec3 v) { return std::min(v.x, std::min(v.y, v.z)); }

}  // namespace

TextureMapping textureMapping(const scene::Node& node, double tileSize) {
    using scene::NodeKind;
    constexpr double kTurn = 2.0 * M_PI;
    switch (node.kind) {
    case NodeKind::Sphere: {
        double r = node.real("radius");
        return {shared::MAP_SPHERICAL, dvec4(r, r, r, 0), dvec4(0.0), 1.0 / (M_PI * r)};
    }
    case NodeKind::Ellipsoid: {
        dvec3 radii = node.vec3("radii");
        return {shared::MAP_SPHERICAL, dvec4(radii, 0), dvec4(0.0), 1.0 / (M_PI * smallest(radii))};
    }
    case NodeKind::Box:
    case NodeKind::RoundBox: {
        dvec3 h = node.vec3("half_extents");
        return {shared::MAP_BOX, dvec4(h, 0), dvec4(0.0), 1.0 / (2.0 * smallest(h))};
    }
    case NodeKind::Plane:
        return {shared::MAP_PLANE, dvec4(glm::normalize(node.vec3("normal")), 1.0 / tileSize), dvec4(0.0),
                1.0 / tileSize};
    case NodeKind::Cylinder: {
        double r = node.real("radius"), h = node.real("half_height");
        return {shared::MAP_CYLINDER, dvec4(r, h, 0, 0), dvec4(0.0), std::max(1.0 / (2.0 * r), 1.0 / (2.0 * h))};
    }
    case NodeKind::Cone: {
        double angle = node.real("angle") * M_PI / 180.0, h = node.real("height");
        double s = std::sin(angle), c = std::cos(angle);
        double base = h * c / s;
        return {shared::MAP_CONE, dvec4(s, c, h, 0), dvec4(0.0), std::max(1.0 / h, 1.0 / (2.0 * base))};
    }
    case NodeKind::Torus: {
        double major = node.real("major_radius"), minor = node.real("minor_radius");
        double inner = std::max(major - minor, minor);  // the shortest way round the axis
        return {shared::MAP_TORUS, dvec4(major, minor, 0, 0), dvec4(0.0),
                std::max(1.0 / (kTurn * inner), 1.0 / (kTurn * minor))};
    }
    case NodeKind::Capsule: {
        dvec3 a = node.vec3("a"), b = node.vec3("b");
        double r = node.real("radius");
        double length = glm::length(b - a) + 2.0 * r;
        return {shared::MAP_CAPSULE, dvec4(a, r), dvec4(b, 0), std::max(1.0 / (kTurn * r), 1.0 / length)};
    }
    default: break;  // formulas are mapped triplanar; the other kinds are no primitives
    }
    throw std::logic_error("no texture mapping for a " + std::string(scene::kindSpec(node.kind).name) + " node");
}

}  // namespace sdfwb::program
