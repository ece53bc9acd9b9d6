#include "program/bounds.h"

#include <algorithm>
#include <cmath>

#include "program/rotation.h"

namespace sdfwb::program {

using glm::dvec3;
using scene::Node;
using scene::NodeKind;

Bounds Bounds::merged(const Bounds& other) const {
    if (empty) return other;
    if (other.empty) return *this;
    if (infinite || other.infinite) return unbounded();
    return box(glm::min(min, other.min), glm::max(max, other.max));
}

Bounds Bounds::intersected(const Bounds& other) const {
    if (empty || other.empty) return Bounds{};
    if (infinite) return other;
    if (other.infinite) return *this;
    dvec3 lo = glm::max(min, other.min), hi = glm::min(max, other.max);
    if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return Bounds{};
    return box(lo, hi);
}

Bounds Bounds::expanded(double amount) const {
    if (empty || infinite) return *this;
    return box(min - dvec3(amount), max + dvec3(amount));
}

double Bounds::radiusAboutY() const {
    double x = std::max(std::abs(min.x), std::abs(max.x)), z = std::max(std::abs(min.z), std::abs(max.z));
    return std::sqrt(x * x + z * z);
}

double Bounds::radiusAboutZ() const {
    double x = std::max(std::abs(min.x), std::abs(max.x)), y = std::max(std::abs(min.y), std::abs(max.y));
    return std::sqrt(x * x + y * y);
}

namespace {

Bounds symmetric(dvec3 halfExtents) { return Bounds::box(-halfExtents, halfExtents); }

Bounds rotated(const Bounds& b, const glm::dmat3& rotation) {
    if (b.empty || b.infinite) return b;
    Bounds result;
    for (int corner = 0; corner < 8; ++corner) {
        dvec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y, (corner & 4) ? b.max.z : b.min.z);
        dvec3 q = rotation * p;
        result = result.merged(Bounds::box(q, q));
    }
    return result;
}

Bounds childrenBounds(const Node& node) {
    Bounds result;
    for (const Node& child : node.children) {
        result = result.merged(nodeBounds(child));
    }
    return result;
}

Bounds firstChildBounds(const Node& node) { return node.children.empty() ? Bounds{} : nodeBounds(node.children[0]); }

Bounds intersectedChildren(const Node& node) {
    if (node.children.empty()) return Bounds{};
    Bounds result = nodeBounds(node.children[0]);
    for (size_t i = 1; i < node.children.size(); ++i) {
        result = result.intersected(nodeBounds(node.children[i]));
    }
    return result;
}

}  // namespace

Bounds nodeBounds(const Node& node) {
    switch (node.kind) {
    case NodeKind::Sphere: return symmetric(dvec3(node.real("radius")));
    case NodeKind::Box:
    case NodeKind::RoundBox: return symmetric(node.vec3("half_extents"));
    case NodeKind::Plane: return Bounds::unbounded();
    case NodeKind::Torus: {
        double R = node.real("major_radius"), r = node.real("minor_radius");
        return symmetric(dvec3(R + r, r, R + r));
    }
    case NodeKind::Cone: {
        // the side satisfies r sin(angle) + y cos(angle) = 0: radius h / tan(angle) at the base y = -h
        double h = node.real("height"), w = h / std::tan(node.real("angle") * M_PI / 180.0);
        return Bounds::box(dvec3(-w, -h, -w), dvec3(w, 0.0, w));
    }
    case NodeKind::Ellipsoid: return symmetric(node.vec3("radii"));
    case NodeKind::Cylinder: {
        double r = node.real("radius");
        return symmetric(dvec3(r, node.real("half_height"), r));
    }
    case NodeKind::Capsule: {
        dvec3 a = node.vec3("a"), b = node.vec3("b");
        return Bounds::box(glm::min(a, b), glm::max(a, b)).expanded(node.real("radius"));
    }
    case NodeKind::Sdf: return Bounds::unbounded();
    case NodeKind::Implicit:
    case NodeKind::Polynomial: return Bounds::box(node.vec3("bounds_min"), node.vec3("bounds_max"));
    case NodeKind::Union: return childrenBounds(node);
    case NodeKind::SmoothUnion: return childrenBounds(node).expanded(node.real("k"));
    case NodeKind::Intersection:
    case NodeKind::SmoothIntersection: return intersectedChildren(node);
    case NodeKind::Difference:
    case NodeKind::SmoothDifference: return firstChildBounds(node);
    case NodeKind::Translate: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        dvec3 v = node.vec3("offset");
        return Bounds::box(b.min + v, b.max + v);
    }
    case NodeKind::Rotate: return rotated(firstChildBounds(node), rotationFromAngles(node.vec3("angles")));
    case NodeKind::Scale: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        double s = node.real("factor");
        return Bounds::box(b.min * s, b.max * s);
    }
    case NodeKind::Twist: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        double r = b.radiusAboutY();
        return Bounds::box(dvec3(-r, b.min.y, -r), dvec3(r, b.max.y, r));
    }
    case NodeKind::Bend: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        double r = b.radiusAboutZ();
        return Bounds::box(dvec3(-r, -r, b.min.z), dvec3(r, r, b.max.z));
    }
    case NodeKind::Round: return firstChildBounds(node).expanded(node.real("radius"));
    case NodeKind::Displace: return firstChildBounds(node).expanded(std::abs(node.real("amplitude")));
    case NodeKind::Elongate: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        dvec3 h = node.vec3("h");
        return Bounds::box(b.min - h, b.max + h);
    }
    case NodeKind::Mirror: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        const std::string& axes = node.text("axes");
        for (int i = 0; i < 3; ++i) {
            if (axes.find(static_cast<char>('x' + i)) != std::string::npos) {
                double m = std::max(std::abs(b.min[i]), std::abs(b.max[i]));
                b.min[i] = -m;
                b.max[i] = m;
            }
        }
        return b;
    }
    case NodeKind::Repeat: {
        Bounds b = firstChildBounds(node);
        if (b.empty || b.infinite) return b;
        dvec3 reach = node.vec3("spacing") * node.vec3("counts");
        // cells reach +-spacing/2 beyond the outermost copy's centre
        return Bounds::box(glm::min(b.min, -node.vec3("spacing") * 0.5) - reach,
                           glm::max(b.max, node.vec3("spacing") * 0.5) + reach);
    }
    case NodeKind::RepeatInfinite: {
        Bounds b = firstChildBounds(node);
        dvec3 period = node.vec3("period");
        if (period != dvec3(0.0)) return Bounds::unbounded();
        return b;
    }
    }
    return Bounds::unbounded();
}

}  // namespace sdfwb::program
