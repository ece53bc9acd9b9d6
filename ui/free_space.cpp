#include "ui/free_space.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "cpu/pick.h"
#include "program/compile_scene.h"
#include "scene/visibility.h"
#include "ui/node_transform.h"

namespace sdfwb::ui {
namespace {

constexpr int kFieldSamples = 5;  // per axis, corners included, when unbounded obstacles exist

// The world bounds of `local` (in the frame `world` maps from): its eight corners mapped.
program::Bounds mapped(const Affine& world, const program::Bounds& local) {
    program::Bounds out;
    for (int corner = 0; corner < 8; ++corner) {
        glm::dvec3 q = world.apply(local.corner(corner));
        out = out.merged(program::Bounds::box(q, q));
    }
    return out;
}

// Bounds touch exactly (a box set down on a top face or the ground): the
// slack covers rounding only. The float field has more error than that.
double boundsSlack(const glm::dvec3& half) { return 1e-9 * std::max({half.x, half.y, half.z}) + 1e-12; }
double fieldSlack(const glm::dvec3& half) { return 1e-3 * std::max({half.x, half.y, half.z}); }

bool overlaps(const program::Bounds& b, const glm::dvec3& lo, const glm::dvec3& hi, double slack) {
    for (int axis = 0; axis < 3; ++axis) {
        if (hi[axis] <= b.min[axis] + slack || b.max[axis] <= lo[axis] + slack) return false;
    }
    return true;
}

}  // namespace

FreeSpace::FreeSpace(const scene::Scene& scene) : scene_(scene) {
    scene::Visibility visibility(scene.root);
    // unions and affine operators are looked through, so that the obstacles
    // are the separate objects (their merged bounds would cover the gaps
    // between them); an explicit stack, as deep trees are legal
    std::vector<std::pair<const scene::Node*, Affine>> pending{{&scene.root, Affine{}}};
    while (!pending.empty()) {
        auto [node, parentFrame] = pending.back();
        pending.pop_back();
        if (!visibility.draws(*node)) continue;
        scene::NodeCategory category = scene::kindSpec(node->kind).category;
        if (node->kind == scene::NodeKind::Union || category == scene::NodeCategory::Affine) {
            Affine inner = parentFrame * ownTransform(*node);
            for (const scene::Node& child : node->children) pending.push_back({&child, inner});
            continue;
        }
        program::Bounds local = program::nodeBounds(*node);
        if (local.empty) continue;
        if (local.infinite) {
            hasUnbounded_ = true;
            continue;
        }
        obstacles_.push_back(mapped(parentFrame, local));
    }
    if (hasUnbounded_) program_ = program::compileScene(scene, {2, 2, 1});  // fields only: any image size
}

bool FreeSpace::isClear(const glm::dvec3& centre, const glm::dvec3& half) const {
    ++tests_;
    double slack = boundsSlack(half);
    const scene::Ground& ground = scene_.environment.ground;
    if (ground.enabled && centre.y - half.y < ground.height - slack) return false;
    glm::dvec3 lo = centre - half, hi = centre + half;
    for (const program::Bounds& b : obstacles_) {
        if (overlaps(b, lo, hi, slack)) return false;
    }
    return !hasUnbounded_ || fieldClear(centre, half);
}

bool FreeSpace::fieldClear(const glm::dvec3& centre, const glm::dvec3& half) const {
    double slack = fieldSlack(half);
    for (int i = 0; i < kFieldSamples; ++i) {
        for (int j = 0; j < kFieldSamples; ++j) {
            for (int k = 0; k < kFieldSamples; ++k) {
                glm::dvec3 f = glm::dvec3(i, j, k) * (2.0 / (kFieldSamples - 1)) - 1.0;  // -1 .. 1 per axis
                if (cpu::fieldDistance(scene_, program_, centre + f * half) < -slack) return false;
            }
        }
    }
    return true;
}

double FreeSpace::restingHeight(const glm::dvec3& centre, const glm::dvec3& half) const {
    double slack = boundsSlack(half), bottom = centre.y - half.y;
    double support = -std::numeric_limits<double>::infinity();
    const scene::Ground& ground = scene_.environment.ground;
    if (ground.enabled && ground.height <= bottom + slack) support = ground.height;
    for (const program::Bounds& b : obstacles_) {
        bool under = b.min.x < centre.x + half.x && centre.x - half.x < b.max.x && b.min.z < centre.z + half.z &&
                     centre.z - half.z < b.max.z;
        if (under && b.max.y <= bottom + slack) support = std::max(support, b.max.y);
    }
    return support == -std::numeric_limits<double>::infinity() ? centre.y : support + half.y;
}

double FreeSpace::highestTop() const {
    const scene::Ground& ground = scene_.environment.ground;
    double top = ground.enabled ? ground.height : -std::numeric_limits<double>::infinity();
    for (const program::Bounds& b : obstacles_) top = std::max(top, b.max.y);
    return top;
}

}  // namespace sdfwb::ui
