#include "ui/transform_handles.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "program/rotation.h"
#include "scene/camera_frame.h"
#include "ui/node_transform.h"
#include "ui/view_picking.h"

namespace sdfwb::ui {
namespace {

using scene::Node;
using scene::NodeKind;

constexpr double kHandleFraction = 0.12;  // of the view's height: the length of an arrow, the radius of a ring
constexpr const char* kDragMergeKey = "handle drag";

bool isTransform(NodeKind kind) {
    return kind == NodeKind::Translate || kind == NodeKind::Rotate || kind == NodeKind::Scale;
}

NodeKind kindOf(HandleMode mode) {
    switch (mode) {
    case HandleMode::Move: return NodeKind::Translate;
    case HandleMode::Rotate: return NodeKind::Rotate;
    case HandleMode::Scale: return NodeKind::Scale;
    }
    return NodeKind::Translate;
}

// The transform a drag edits: the node at `path`, or (wrap) a new one to be
// put around the node at `path`. `content` is the node the chain of
// transform wrappers holds: its origin is where the node sits.
struct Site {
    NodePath path;
    bool wrap = false;
    NodePath content;
};

Site siteFor(const Node& root, const NodePath& target, NodeKind kind) {
    NodePath content = target;
    for (const Node* n = findNode(root, content); isTransform(n->kind) && n->children.size() == 1; n = &n->children[0]) {
        if (n->kind == kind) return {content, false, content};
        content.push_back(0);
    }
    NodePath outermost = content;
    for (NodePath up = content; !up.empty();) {
        up = parentOf(up);
        const Node& parent = *findNode(root, up);
        if (!isTransform(parent.kind)) break;
        if (parent.kind == kind) return {up, false, content};
        outermost = up;
    }
    // a new translate outside the chain, a new rotate or scale right around the content
    return {kind == NodeKind::Translate ? outermost : content, true, content};
}

glm::dvec3 pivotOf(const Node& root, const Site& site, HandleMode mode) {
    const NodePath& at = mode == HandleMode::Move || site.wrap ? site.content : site.path;
    return worldFromInner(root, at).offset;
}

glm::dvec3 axisVector(int axis) {
    glm::dvec3 e(0.0);
    e[axis] = 1.0;
    return e;
}

double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    glm::dvec2 ab = b - a;
    double len2 = glm::dot(ab, ab);
    double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// The parameter along the line pivot + s * axis closest to the ray (nullopt when they are parallel).
std::optional<double> closestOnAxis(const ViewRay& ray, const glm::dvec3& pivot, const glm::dvec3& axis) {
    glm::dvec3 w = pivot - ray.origin;
    double b = glm::dot(axis, ray.direction);
    double denominator = 1.0 - b * b;
    if (denominator < 1e-6) return std::nullopt;
    return (b * glm::dot(w, ray.direction) - glm::dot(w, axis)) / denominator;
}

// Where the ray meets the plane through `pivot` across `normal`, as an offset from the pivot.
std::optional<glm::dvec3> onPlane(const ViewRay& ray, const glm::dvec3& pivot, const glm::dvec3& normal) {
    double across = glm::dot(ray.direction, normal);
    if (std::abs(across) < 1e-3) return std::nullopt;
    double t = glm::dot(pivot - ray.origin, normal) / across;
    if (t <= 0) return std::nullopt;
    return ray.origin + t * ray.direction - pivot;
}

double snapped(double value, double step, bool snap) { return snap ? std::round(value / step) * step : value; }

}  // namespace

std::optional<HandleMode> handleModeNamed(std::string_view name) {
    for (int i = 0; i < 3; ++i) {
        if (name == kHandleModeNames[i]) return static_cast<HandleMode>(i);
    }
    return std::nullopt;
}

std::optional<HandleLayout> handleLayout(const scene::Scene& scene, const NodePath& path, HandleMode mode, int width,
                                         int height) {
    // a node that does not draw (hidden, or left out by a solo) gets no handles
    if (width <= 0 || height <= 0 || !drawsAt(scene.root, path)) return std::nullopt;
    HandleLayout layout;
    layout.pivotWorld = pivotOf(scene.root, siteFor(scene.root, path, kindOf(mode)), mode);
    std::optional<glm::dvec2> pivot = projectToView(scene, layout.pivotWorld, width, height);
    if (!pivot) return std::nullopt;
    layout.pivot = *pivot;
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    double pixels = kHandleFraction * height;
    double length = glm::dot(layout.pivotWorld - frame.eye, frame.forward) * 2.0 * kHandleFraction * frame.tanHalfFov;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 e = axisVector(axis);
        if (mode == HandleMode::Rotate) {
            glm::dvec3 u = axisVector((axis + 1) % 3), v = axisVector((axis + 2) % 3);
            for (int i = 0; i < HandleLayout::kRingPoints; ++i) {
                double phi = 2.0 * std::numbers::pi * i / HandleLayout::kRingPoints;
                std::optional<glm::dvec2> p = projectToView(
                    scene, layout.pivotWorld + length * (std::cos(phi) * u + std::sin(phi) * v), width, height);
                if (!p) {
                    layout.visible[axis] = false;
                    break;
                }
                layout.ring[axis][i] = *p;
            }
            // seen edge on, a ring is a line: still a handle (the drag then turns by the screen angle)
        } else {
            std::optional<glm::dvec2> tip = projectToView(scene, layout.pivotWorld + length * e, width, height);
            layout.visible[axis] = tip && glm::length(*tip - layout.pivot) > 0.2 * pixels;
            if (tip) layout.tip[axis] = *tip;
        }
    }
    return layout;
}

std::optional<int> handleAt(const HandleLayout& layout, HandleMode mode, const glm::dvec2& point) {
    std::optional<int> best;
    double nearest = kHandleReach;
    for (int axis = 0; axis < 3; ++axis) {
        if (!layout.visible[axis]) continue;
        double d = std::numeric_limits<double>::infinity();
        if (mode == HandleMode::Rotate) {
            const auto& ring = layout.ring[axis];
            for (size_t i = 0; i < ring.size(); ++i) d = std::min(d, segmentDistance(point, ring[i], ring[(i + 1) % ring.size()]));
        } else {
            d = segmentDistance(point, layout.pivot, layout.tip[axis]);
        }
        if (d <= nearest) {
            nearest = d;
            best = axis;
        }
    }
    return best;
}

std::optional<HandleGrip> handleGrip(const HandleLayout& layout, HandleMode mode, int axis) {
    if (!layout.visible[axis]) return std::nullopt;
    if (mode != HandleMode::Rotate) {
        glm::dvec2 along = layout.tip[axis] - layout.pivot;
        return HandleGrip{layout.pivot + 0.8 * along, glm::normalize(along)};
    }
    // the ring's point farthest from the pivot on screen, clear of the other rings' crossings
    const auto& ring = layout.ring[axis];
    size_t far = 0;
    for (size_t i = 1; i < ring.size(); ++i) {
        if (glm::length(ring[i] - layout.pivot) > glm::length(ring[far] - layout.pivot)) far = i;
    }
    glm::dvec2 tangent = ring[(far + 1) % ring.size()] - ring[(far + ring.size() - 1) % ring.size()];
    if (glm::length(tangent) < 1e-9) return std::nullopt;
    return HandleGrip{ring[far], glm::normalize(tangent)};
}

bool HandleDrag::begin(const Editor& editor, HandleMode mode, int width, int height, const glm::dvec2& point) {
    active_ = false;
    if (!editor.selection()) return false;
    std::optional<HandleLayout> layout = handleLayout(editor.scene(), *editor.selection(), mode, width, height);
    if (!layout) return false;
    std::optional<int> axis = handleAt(*layout, mode, point);
    if (!axis) return false;
    start_ = editor.scene();
    target_ = *editor.selection();
    mode_ = mode;
    layout_ = *layout;
    axis_ = *axis;
    width_ = width;
    height_ = height;
    press_ = point;
    active_ = true;
    return true;
}

Problems HandleDrag::update(Editor& editor, const glm::dvec2& point, bool snap) {
    if (!active_) return {};
    const NodeKind kind = kindOf(mode_);
    const glm::dvec3 e = axisVector(axis_);
    ViewRay from = viewRay(start_, width_, height_, press_), to = viewRay(start_, width_, height_, point);

    // the change the mouse asks for; none when the geometry gives no answer
    double change = mode_ == HandleMode::Scale ? 1.0 : 0.0;
    switch (mode_) {
    case HandleMode::Move: {
        std::optional<double> s0 = closestOnAxis(from, layout_.pivotWorld, e), s1 = closestOnAxis(to, layout_.pivotWorld, e);
        if (s0 && s1) change = snapped(*s1 - *s0, kMoveSnap, snap);
        break;
    }
    case HandleMode::Rotate: {
        std::optional<glm::dvec3> a = onPlane(from, layout_.pivotWorld, e), b = onPlane(to, layout_.pivotWorld, e);
        double turn = 0;
        if (a && b) {
            turn = std::atan2(glm::dot(glm::cross(*a, *b), e), glm::dot(*a, *b));
        } else {  // the ring seen edge on: the angle round the pivot on screen, turning as the axis faces
            glm::dvec2 p = press_ - layout_.pivot, q = point - layout_.pivot;
            double facing = glm::dot(e, scene::cameraFrame(start_.camera).forward) > 0 ? 1.0 : -1.0;
            turn = facing * std::atan2(p.x * q.y - p.y * q.x, glm::dot(p, q));
        }
        change = snapped(turn * 180.0 / std::numbers::pi, kRotateSnap, snap);
        break;
    }
    case HandleMode::Scale: {
        double reach = glm::length(press_ - layout_.pivot);
        if (reach >= 1.0) change = std::max(snapped(glm::length(point - layout_.pivot) / reach, kScaleSnap, snap), snap ? kScaleSnap : 1e-3);
        break;
    }
    }
    bool identity = change == (mode_ == HandleMode::Scale ? 1.0 : 0.0);
    Node root = start_.root;
    NodePath selection = target_;
    if (!identity) {
        Site site = siteFor(root, target_, kind);
        if (site.wrap) {
            Node* slot = findNode(root, site.path);
            Node wrapper = Node::make(kind);
            wrapper.children.push_back(std::move(*slot));
            *slot = std::move(wrapper);
            if (isWithin(target_, site.path)) selection.insert(selection.begin() + static_cast<long>(site.path.size()), 0);
        }
        Affine parent = site.path.empty() ? Affine{} : worldFromInner(root, parentOf(site.path));
        Node& node = *findNode(root, site.path);
        switch (mode_) {
        case HandleMode::Move:
            node.set("offset", node.vec3("offset") + glm::inverse(parent.linear) * (change * e));
            break;
        case HandleMode::Rotate: {
            glm::dmat3 turn = program::rotationFromAngles(change * e);
            glm::dmat3 r = glm::inverse(parent.linear) * turn * parent.linear * program::rotationFromAngles(node.vec3("angles"));
            node.set("angles", program::anglesFromRotation(r, node.vec3("angles")));
            break;
        }
        case HandleMode::Scale: node.set("factor", node.real("factor") * change); break;
        }
    }
    if (root == editor.scene().root) return {};  // a still mouse: no edit, no re-render
    static constexpr const char* kLabels[] = {"Move", "Rotate", "Scale"};
    Problems problems =
        editor.apply(kLabels[static_cast<int>(mode_)], [&root](scene::Scene& s) { s.root = std::move(root); }, kDragMergeKey);
    if (problems.empty()) editor.select(selection);
    return problems;
}

void HandleDrag::end(Editor& editor) {
    if (active_) editor.endMerge();
    active_ = false;
}

}  // namespace sdfwb::ui
