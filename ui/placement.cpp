#include "ui/placement.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "cpu/pick.h"
#include "program/bounds.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "ui/node_transform.h"
#include "ui/view_camera.h"

namespace sdfwb::ui {
namespace {

constexpr int kClearingSteps = 32;  // moves toward the eye before giving up on a free spot
constexpr int kSettlingSteps = 16;  // bisections back towards the last spot that was not free
constexpr double kGap = 0.1;        // between a duplicate and its original, of the original's size

// How far a box of half extents `half` reaches along unit direction `n`.
double support(const glm::dvec3& half, const glm::dvec3& n) {
    return std::abs(half.x * n.x) + std::abs(half.y * n.y) + std::abs(half.z * n.z);
}

// A box of half extents `half` centred at `centre` is clear of everything
// in the scene (the ground included) when the field there reaches past it
// in the direction of the nearest surface.
bool isClear(const scene::Scene& scene, const program::Program& program, const glm::dvec3& centre,
             const glm::dvec3& half) {
    double d = cpu::fieldDistance(scene, program, centre);
    return d >= 0.999 * support(half, cpu::fieldNormal(scene, program, centre));
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

// Moves `point` along `direction` until a box of half extents `half` there is
// clear and `allowed`; false when not within kClearingSteps steps, or (with
// `stopWhenRefused`) once a step is not allowed.
template <typename Allowed>
bool clearAlong(const scene::Scene& scene, const program::Program& program, glm::dvec3& point, const glm::dvec3& half,
                const glm::dvec3& direction, Allowed allowed, bool stopWhenRefused) {
    glm::dvec3 moved = point, blocked = point;
    auto free = [&](const glm::dvec3& p) { return allowed(p) && isClear(scene, program, p, half); };
    for (int i = 0; i < kClearingSteps; ++i) {
        bool ok = allowed(moved);
        if (ok && isClear(scene, program, moved, half)) {
            // a step can overshoot the free spot by up to the box's reach:
            // back to just clear, so the box touches what it was moved off
            for (int k = 0; k < kSettlingSteps && i > 0; ++k) {
                glm::dvec3 middle = 0.5 * (blocked + moved);
                (free(middle) ? moved : blocked) = middle;
            }
            point = moved;
            return true;
        }
        if (!ok && stopWhenRefused) return false;
        blocked = moved;
        double reach = support(half, direction);
        double d = cpu::fieldDistance(scene, program, moved);
        moved += direction * std::max(reach - d, 0.05 * reach + 1e-3);
    }
    return false;
}

}  // namespace

glm::dvec3 placementPoint(const scene::Scene& scene, const glm::dvec3& half) {
    program::Program program = program::compileScene(scene, {2, 2, 1});  // fields only: any image size
    cpu::PickResult centre = cpu::pickViewCentre(scene);
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    glm::dvec3 point = centre.hit ? centre.position + centre.normal * support(half, centre.normal) : scene.camera.target;
    // inside or through something (a gap too narrow, a target inside a solid):
    // rise until free (on top of what is there) as long as the box still
    // covers the view centre, else come towards the eye along the centre ray,
    // never around or behind the eye; else go beyond in front of the eye and
    // not around it
    auto inFront = [&](const glm::dvec3& p) {
        glm::dvec3 gap = glm::abs(p - frame.eye) - 1.1 * half;
        return glm::dot(p - frame.eye, frame.forward) > 0 && std::max({gap.x, gap.y, gap.z}) > 0;
    };
    auto seenAtCentre = [&](const glm::dvec3& p) {
        glm::dvec3 off = p - frame.eye;
        off -= frame.forward * glm::dot(off, frame.forward);  // from the centre ray to p
        double distance = glm::length(off);
        return inFront(p) && (distance < 1e-12 || distance <= support(half, off / distance) * (1.0 + 1e-9));
    };
    // a surface right in front of the eye leaves no room: farther along the ray
    double nearest = support(half, frame.forward);
    if (!inFront(point)) point += frame.forward * (nearest - glm::dot(point - frame.eye, frame.forward));
    auto anywhere = [](const glm::dvec3&) { return true; };
    if (!clearAlong(scene, program, point, half, glm::dvec3(0, 1, 0), seenAtCentre, true) &&
        !clearAlong(scene, program, point, half, -frame.forward, inFront, true)) {
        // no room in front: beyond, level (the ground stays below)
        glm::dvec3 level = glm::dvec3(frame.forward.x, 0, frame.forward.z);
        double length = glm::length(level);
        clearAlong(scene, program, point, half, length > 1e-6 ? level / length : glm::dvec3(0, 1, 0), anywhere, false);
    }
    return point;
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
    program::Program program = program::compileScene(scene, {2, 2, 1});
    scene::CameraFrame frame = scene::cameraFrame(scene.camera);
    glm::dvec3 half = 0.5 * (bounds.max - bounds.min), centre = 0.5 * (bounds.min + bounds.max);
    // beside the original as the user sees it: right, left, above, behind
    glm::dvec3 shift(0.0);
    for (const glm::dvec3& direction : {frame.right, -frame.right, frame.up, frame.forward}) {
        glm::dvec3 candidate = direction * (2.0 + kGap) * support(half, direction);
        if (shift == glm::dvec3(0.0)) shift = candidate;  // if nothing is clear, to the right
        if (isClear(scene, program, centre + candidate, half)) {
            shift = candidate;
            break;
        }
    }
    glm::dvec3 localShift = glm::inverse(worldFromInner(scene.root, parentOf(path)).linear) * shift;
    NodePath within(selected.begin() + static_cast<long>(path.size()), selected.end());
    return insertShifted(editor, parentOf(path), path.back() + 1, *node, localShift, "Duplicate", within);
}

}  // namespace sdfwb::ui
