#pragma once
// Whether a world-aligned box is clear of what a scene draws: the test that
// placement runs on each spot it considers for a new or duplicated node.
//
// The drawn geometry is split, from the root down through unions and the
// affine operators, into obstacles with conservative world bounds (a
// primitive, or an operator whose frame is not affine, taken whole). A box is
// clear when it overlaps none of them and stays above an enabled ground: a
// proof, since the bounds enclose what they bound, that lets a box rest on
// the ground or on a box's top face. Unbounded obstacles (a plane, an sdf
// formula, an infinite repetition) have no bounds: when the scene has any,
// the scene's field is also sampled on a fixed grid over the box and must not
// be inside anything there (a sample test, not a proof: a feature thinner
// than the grid can slip between samples).

#include <vector>

#include <glm/vec3.hpp>

#include "program/bounds.h"
#include "program/program.h"
#include "scene/scene.h"

namespace sdfwb::ui {

class FreeSpace {
public:
    // Keeps a reference to the scene, which must outlive it (so no temporary).
    explicit FreeSpace(const scene::Scene& scene);
    explicit FreeSpace(const scene::Scene&& scene) = delete;

    // Whether the box of half extents `half` centred at `centre` overlaps no
    // drawn geometry: bounds may touch it (up to rounding), the sampled field
    // may dip below zero by a thousandth of the box's size (float error).
    bool isClear(const glm::dvec3& centre, const glm::dvec3& half) const;

    // The height of `centre` that sets the box on the highest support under
    // it (the ground or an obstacle's top, whichever is highest at or below
    // its bottom); `centre.y` when nothing bounded supports it.
    double restingHeight(const glm::dvec3& centre, const glm::dvec3& half) const;

    // The highest top of the bounded obstacles and the ground; the ground's
    // height (or -infinity) when there are none.
    double highestTop() const;

    // How many isClear calls were answered: the work a search did.
    int tests() const { return tests_; }

    const std::vector<program::Bounds>& obstacles() const { return obstacles_; }
    bool hasUnbounded() const { return hasUnbounded_; }

private:
    bool fieldClear(const glm::dvec3& centre, const glm::dvec3& half) const;

    const scene::Scene& scene_;
    std::vector<program::Bounds> obstacles_;  // world bounds, none empty or infinite
    bool hasUnbounded_ = false;
    program::Program program_;  // compiled only when hasUnbounded_
    mutable int tests_ = 0;
};

}  // namespace sdfwb::ui
