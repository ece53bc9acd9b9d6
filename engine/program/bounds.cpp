#include "program/bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

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
        dvec3 q = rotation * b.corner(corner);
        result = result.merged(Bounds::box(q, q));
    }
    return result;
}

// ---- one entry per node kind (kBoundsRules): a node's bounds from its children's ----
using Children = std::span<const Bounds>;

Bounds unbounded(const Node&, Children) { return Bounds::unbounded(); }
Bounds sphereBounds(const Node& n, Children) { return symmetric(dvec3(n.real("radius"))); }
Bounds boxBounds(const Node& n, Children) { return symmetric(n.vec3("half_extents")); }
Bounds torusBounds(const Node& n, Children) {
    double R = n.real("major_radius"), r = n.real("minor_radius");
    return symmetric(dvec3(R + r, r, R + r));
}
Bounds coneBounds(const Node& n, Children) {
    // the side satisfies r sin(angle) + y cos(angle) = 0: radius h / tan(angle) at the base y = -h
    double h = n.real("height"), w = h / std::tan(n.real("angle") * M_PI / 180.0);
    return Bounds::box(dvec3(-w, -h, -w), dvec3(w, 0.0, w));
}
Bounds ellipsoidBounds(const Node& n, Children) { return symmetric(n.vec3("radii")); }
Bounds cylinderBounds(const Node& n, Children) {
    double r = n.real("radius");
    return symmetric(dvec3(r, n.real("half_height"), r));
}
Bounds capsuleBounds(const Node& n, Children) {
    dvec3 a = n.vec3("a"), b = n.vec3("b");
    return Bounds::box(glm::min(a, b), glm::max(a, b)).expanded(n.real("radius"));
}
Bounds boxFieldBounds(const Node& n, Children) { return Bounds::box(n.vec3("bounds_min"), n.vec3("bounds_max")); }

Bounds mergedChildren(const Node&, Children c) {
    Bounds result;
    for (const Bounds& b : c) result = result.merged(b);
    return result;
}
Bounds smoothUnionBounds(const Node& n, Children c) { return mergedChildren(n, c).expanded(n.real("k")); }
Bounds intersectedChildren(const Node&, Children c) {
    if (c.empty()) return Bounds{};
    Bounds result = c[0];
    for (size_t i = 1; i < c.size(); ++i) result = result.intersected(c[i]);
    return result;
}
Bounds firstChild(const Node&, Children c) { return c.empty() ? Bounds{} : c[0]; }

Bounds translateBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    dvec3 v = n.vec3("offset");
    return Bounds::box(b.min + v, b.max + v);
}
Bounds rotateBounds(const Node& n, Children c) {
    return rotated(firstChild(n, c), rotationFromAngles(n.vec3("angles")));
}
Bounds scaleBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    double s = n.real("factor");
    return Bounds::box(b.min * s, b.max * s);
}
Bounds twistBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    double r = b.radiusAboutY();
    return Bounds::box(dvec3(-r, b.min.y, -r), dvec3(r, b.max.y, r));
}
Bounds bendBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    double r = b.radiusAboutZ();
    return Bounds::box(dvec3(-r, -r, b.min.z), dvec3(r, r, b.max.z));
}
Bounds roundBounds(const Node& n, Children c) { return firstChild(n, c).expanded(n.real("radius")); }
Bounds displaceBounds(const Node& n, Children c) { return firstChild(n, c).expanded(std::abs(n.real("amplitude"))); }
Bounds elongateBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    dvec3 h = n.vec3("h");
    return Bounds::box(b.min - h, b.max + h);
}
Bounds mirrorBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    const std::string& axes = n.text("axes");
    for (int i = 0; i < 3; ++i) {
        if (axes.find(static_cast<char>('x' + i)) != std::string::npos) {
            double m = std::max(std::abs(b.min[i]), std::abs(b.max[i]));
            b.min[i] = -m;
            b.max[i] = m;
        }
    }
    return b;
}
Bounds repeatBounds(const Node& n, Children c) {
    Bounds b = firstChild(n, c);
    if (b.empty || b.infinite) return b;
    dvec3 reach = n.vec3("spacing") * n.vec3("counts");
    // cells reach +-spacing/2 beyond the outermost copy's centre
    return Bounds::box(glm::min(b.min, -n.vec3("spacing") * 0.5) - reach,
                       glm::max(b.max, n.vec3("spacing") * 0.5) + reach);
}
Bounds repeatInfiniteBounds(const Node& n, Children c) {
    if (n.vec3("period") != dvec3(0.0)) return Bounds::unbounded();
    return firstChild(n, c);
}

struct BoundsRule {
    NodeKind kind;
    Bounds (*bounds)(const Node&, Children);
};

using enum NodeKind;
constexpr std::array<BoundsRule, scene::kNodeKindCount> kBoundsRules = {{
    {Sphere, sphereBounds},
    {Box, boxBounds},
    {RoundBox, boxBounds},
    {Plane, unbounded},
    {Torus, torusBounds},
    {Cone, coneBounds},
    {Ellipsoid, ellipsoidBounds},
    {Cylinder, cylinderBounds},
    {Capsule, capsuleBounds},
    {Union, mergedChildren},
    {Intersection, intersectedChildren},
    {Difference, firstChild},
    {SmoothUnion, smoothUnionBounds},
    {SmoothIntersection, intersectedChildren},
    {SmoothDifference, firstChild},
    {Translate, translateBounds},
    {Rotate, rotateBounds},
    {Scale, scaleBounds},
    {Twist, twistBounds},
    {Bend, bendBounds},
    {Round, roundBounds},
    {Displace, displaceBounds},
    {Elongate, elongateBounds},
    {Mirror, mirrorBounds},
    {Repeat, repeatBounds},
    {RepeatInfinite, repeatInfiniteBounds},
    {Sdf, unbounded},
    {Implicit, boxFieldBounds},
    {Polynomial, boxFieldBounds},
}};
static_assert(scene::inKindOrder(kBoundsRules), "kBoundsRules must list every node kind in NodeKind order");

}  // namespace

// Post-order over an explicit stack, so a deep chain of operators needs no deep
// call stack: a node's rule runs once its children's bounds are on `results`.
Bounds nodeBounds(const Node& root) {
    if (root.hidden) return {};  // draws nothing (scene/visibility.h; solo is left out: these bounds may be larger)
    struct Pending {
        const Node* node;
        size_t nextChild;
    };
    std::vector<Pending> stack{{&root, 0}};
    std::vector<Bounds> results;
    while (!stack.empty()) {
        Pending& top = stack.back();
        if (top.nextChild < top.node->children.size()) {
            const Node* child = &top.node->children[top.nextChild++];
            if (child->hidden) {
                results.push_back({});
                continue;
            }
            stack.push_back({child, 0});
            continue;
        }
        const Node& node = *top.node;
        stack.pop_back();
        size_t first = results.size() - node.children.size();
        Bounds b = kBoundsRules[static_cast<size_t>(node.kind)].bounds(
            node, Children(results.data() + first, node.children.size()));
        results.resize(first);
        results.push_back(b);
    }
    return results.back();
}

}  // namespace sdfwb::program
