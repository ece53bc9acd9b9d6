#include "ui/placement.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cpu/pick.h"
#include "program/bounds.h"
#include "scene/camera_frame.h"
#include "ui/free_space.h"
#include "ui/node_transform.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {
namespace {

constexpr double kGap = 0.1;       // between a duplicate and its original, of the original's size
constexpr double kViewCone = 0.9;  // of the view's half angle: a spot's centre stays inside the picture

// How far a box of half extents `half` reaches along unit direction `n`.
double support(const glm::dvec3& half, const glm::dvec3& n) {
    return std::abs(half.x * n.x) + std::abs(half.y * n.y) + std::abs(half.z * n.z);
}

// The spots a search may pick from, for a box of half extents `half`.
struct Spots {
    const FreeSpace& space;
    scene::CameraFrame frame;
    glm::dvec3 half;
    bool setsDown;  // a spot may be set down on what is under it

    // in front of the eye, the box not around it
    bool inFront(const glm::dvec3& p) const {
        glm::dvec3 gap = glm::abs(p - frame.eye) - 1.1 * half;
        return glm::dot(p - frame.eye, frame.forward) > 0 && std::max({gap.x, gap.y, gap.z}) > 0;
    }
    // the centre inside a cone within the picture (the vertical field of view, the narrower one)
    bool inView(const glm::dvec3& p) const {
        glm::dvec3 off = p - frame.eye;
        double along = glm::dot(off, frame.forward);
        return along > 0 && glm::length(off - along * frame.forward) <= kViewCone * frame.tanHalfFov * along;
    }
    bool free(const glm::dvec3& p) const { return inFront(p) && inView(p) && space.isClear(p, half); }
    // Where the box goes for the spot `p`: set down on what is under it (a
    // floor, a top face) when that is free, else on p's level when that is;
    // two clearance tests at most.
    std::optional<glm::dvec3> freeAt(const glm::dvec3& p) const {
        if (setsDown) {
            glm::dvec3 down(p.x, space.restingHeight(p, half), p.z);
            if (down != p && free(down)) return down;
        }
        if (free(p)) return p;
        return std::nullopt;
    }
};

// The nearest free spot to `first` on rings around it on its level, within
// the budget; nullopt when none is free.
std::optional<glm::dvec3> searchRings(const Spots& spots, const glm::dvec3& first, double step) {
    if (std::optional<glm::dvec3> here = spots.freeAt(first)) return here;
    // right and left first (beside what is in the way as the user sees it),
    // then round to behind and towards the eye
    constexpr std::array<double, kPlacementDirections> kAngles = {0,  180, 30,  150, 330, 210,
                                                                  60, 120, 300, 240, 90,  270};
    glm::dvec3 across(spots.frame.right.x, 0, spots.frame.right.z),
        ahead(spots.frame.forward.x, 0, spots.frame.forward.z);
    across = glm::length(across) > 1e-6 ? glm::normalize(across) : glm::dvec3(1, 0, 0);
    ahead = glm::length(ahead) > 1e-6 ? glm::normalize(ahead) : glm::cross(glm::dvec3(0, 1, 0), across);
    for (int ring = 1; ring <= kPlacementRings; ++ring) {
        for (double angle : kAngles) {
            double a = glm::radians(angle);
            glm::dvec3 direction = std::cos(a) * across + std::sin(a) * ahead;
            auto at = [&](double radius) { return spots.freeAt(first + radius * direction); };
            std::optional<glm::dvec3> found = at(ring * step);
            if (!found) continue;
            // a ring step can overshoot the free spot: back towards the first
            // spot while free, so the box lands beside what was in the way
            double blocked = (ring - 1) * step, clear = ring * step;
            for (int k = 0; k < kPlacementSettlingSteps; ++k) {
                double middle = 0.5 * (blocked + clear);
                if (std::optional<glm::dvec3> closer = at(middle)) {
                    clear = middle;
                    found = closer;
                } else {
                    blocked = middle;
                }
            }
            return found;
        }
    }
    return std::nullopt;
}

// The search from `first`: the rings, else above everything there, else `first`.
PlacementSearch searchFrom(const scene::Scene& scene, const glm::dvec3& first, const glm::dvec3& half, bool setsDown) {
    FreeSpace space(scene);
    Spots spots{space, scene::cameraFrame(scene.camera), half, setsDown};
    // rings a box's size apart, or a share of the view for a small box
    double step = std::max({0.5 * std::max(half.x, half.z), 0.04 * scene.camera.distance, 1e-3});
    if (std::optional<glm::dvec3> found = searchRings(spots, first, step)) return {*found, true, space.tests()};
    glm::dvec3 above(first.x, std::max(first.y, space.highestTop() + half.y), first.z);
    bool clear = spots.inFront(above) && space.isClear(above, half);
    return {clear ? above : first, clear, space.tests()};
}

// The world half extents of a box of local half extents `half` under `linear`.
glm::dvec3 worldHalfExtents(const glm::dmat3& linear, const glm::dvec3& half) {
    glm::dvec3 out(0.0);
    for (int column = 0; column < 3; ++column) out += glm::abs(linear[column]) * half[column];
    return out;
}

// `node` moved by `offset` in its parent's frame: its own translate shifted,
// or a new translate around it. Whether it was wrapped goes to `wrapped`.
scene::Node shifted(scene::Node node, const glm::dvec3& offset, bool& wrapped) {
    wrapped = node.kind != scene::NodeKind::Translate;
    if (!wrapped) {
        node.set("offset", node.vec3("offset") + offset);
        return node;
    }
    scene::Node translate = scene::Node::make(scene::NodeKind::Translate);
    translate.set("offset", offset);
    translate.children.push_back(std::move(node));
    return translate;
}

// Inserts the shifted node and selects `select` inside it (a path relative to the node).
Problems insertShifted(Editor& editor, const NodePath& parent, int index, scene::Node node, const glm::dvec3& offset,
                       const std::string& label, const NodePath& select = {}) {
    bool wrapped = false;
    Problems problems = editor.insert(parent, index, shifted(std::move(node), offset, wrapped), label);
    if (problems.empty()) {
        NodePath inner = *editor.selection();
        if (wrapped) inner.push_back(0);
        inner.insert(inner.end(), select.begin(), select.end());
        editor.select(inner);
    }
    return problems;
}

bool takesAnotherChild(const scene::Node& node) {
    int most = scene::kindSpec(node.kind).maxChildren;
    return most < 0 || static_cast<int>(node.children.size()) < most;
}

}  // namespace

PlacementSearch searchPlacement(const scene::Scene& scene, const glm::dvec3& half) {
    cpu::PickResult centre = cpu::pickViewCentre(scene);
    // the float march lands on the ground plane to within its rounding, on
    // either side; a box set on it goes on the plane itself
    if (centre.hit && centre.ground) centre.position.y = scene.environment.ground.height;
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    glm::dvec3 first =
        centre.hit ? centre.position + centre.normal * support(half, centre.normal) : scene.camera.target;
    // a surface right in front of the eye leaves no room: farther along the ray
    double nearest = support(half, frame.forward);
    if (glm::dot(first - frame.eye, frame.forward) < nearest) {
        first += frame.forward * (nearest - glm::dot(first - frame.eye, frame.forward));
    }
    // looking at something, spots are set down on what is under them (in
    // front of a wall, on the floor before it); in the open they stay level
    return searchFrom(scene, first, half, centre.hit);
}

glm::dvec3 placementPoint(const scene::Scene& scene, const glm::dvec3& half) {
    return searchPlacement(scene, half).point;
}

Problems insertPlaced(Editor& editor, const NodePath& parent, int index, scene::Node node) {
    program::Bounds local = program::nodeBounds(node);
    std::string label = "Add " + std::string(scene::kindSpec(node.kind).name);
    if (local.empty || local.infinite || !findNode(editor.scene().root, parent)) {
        return editor.insert(parent, index, std::move(node), label);
    }
    Affine frame = worldFromInner(editor.scene().root, parent);
    glm::dvec3 half = worldHalfExtents(frame.linear, 0.5 * (local.max - local.min));
    glm::dvec3 at = placementPoint(editor.scene(), half);
    glm::dvec3 offset = frame.inverse().apply(at) - 0.5 * (local.min + local.max);
    return insertShifted(editor, parent, index, std::move(node), offset, label);
}

Problems addPlaced(Editor& editor, scene::Node node) {
    std::optional<std::pair<NodePath, int>> where = editor.insertionPoint(std::nullopt);
    if (!where) return editor.add(std::move(node), std::nullopt);  // its message
    return insertPlaced(editor, where->first, where->second, std::move(node));
}

Problems addPlaced(Editor& editor, scene::NodeKind kind) {
    if (scene::kindSpec(kind).minChildren > 0) return editor.add(kind, std::nullopt);  // wraps the selection
    return addPlaced(editor, scene::Node::make(kind));
}

Problems duplicatePlaced(Editor& editor, const NodePath& selected) {
    const scene::Scene& scene = editor.scene();
    // a node alone in a translate (or any one-child wrapper) is copied with
    // its wrappers: the copy keeps its transform and has a parent to go into
    NodePath path = selected;
    while (path.size() > 1 && findNode(scene.root, path) && !takesAnotherChild(*findNode(scene.root, parentOf(path)))) {
        path = parentOf(path);
    }
    const scene::Node* node = findNode(scene.root, path);
    program::Bounds bounds = node && !path.empty() ? worldBounds(scene.root, path) : program::Bounds{};
    if (bounds.empty || bounds.infinite) return editor.duplicate(path);
    FreeSpace space(scene);
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    glm::dvec3 half = 0.5 * (bounds.max - bounds.min), centre = 0.5 * (bounds.min + bounds.max);
    // beside the original as the user sees it: right, left, above, behind
    std::optional<glm::dvec3> shift;
    for (const glm::dvec3& direction : {frame.right, -frame.right, frame.up, frame.forward}) {
        glm::dvec3 candidate = direction * (2.0 + kGap) * support(half, direction);
        if (space.isClear(centre + candidate, half)) {
            shift = candidate;
            break;
        }
    }
    // all four taken: the nearest free spot around the one to the right
    if (!shift) {
        glm::dvec3 right = centre + frame.right * (2.0 + kGap) * support(half, frame.right);
        shift = searchFrom(scene, right, half, false).point - centre;
    }
    glm::dvec3 localShift = glm::inverse(worldFromInner(scene.root, parentOf(path)).linear) * *shift;
    NodePath within(selected.begin() + static_cast<long>(path.size()), selected.end());
    return insertShifted(editor, parentOf(path), path.back() + 1, *node, localShift, "Duplicate", within);
}

}  // namespace sdfwb::ui
