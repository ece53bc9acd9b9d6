#pragma once
// Conservative axis-aligned bounds of scene subtrees, in the subtree's own frame.
// Used for the Lipschitz step factor of twist and bend and for framing the camera.

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace sdfwb::program {

struct Bounds {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    bool empty = true;     // encloses nothing
    bool infinite = false; // unbounded in some direction
    bool finite() const { return !empty && !infinite; }  // a box that encloses something

    static Bounds box(glm::dvec3 lo, glm::dvec3 hi) { return {lo, hi, false, false}; }
    static Bounds unbounded() { return {glm::dvec3(0.0), glm::dvec3(0.0), false, true}; }
    Bounds merged(const Bounds& other) const;
    Bounds intersected(const Bounds& other) const;
    Bounds expanded(double amount) const;
    // Corner `index` (0..7): bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::dvec3 corner(int index) const {
        return {(index & 1) ? max.x : min.x, (index & 2) ? max.y : min.y, (index & 4) ? max.z : min.z};
    }
    // Largest distance from the y axis (twist) or z axis (bend) of any bounded point.
    double radiusAboutY() const;
    double radiusAboutZ() const;
};

Bounds nodeBounds(const scene::Node& node);

}  // namespace sdfwb::program
