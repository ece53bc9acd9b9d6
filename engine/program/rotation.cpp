#include "program/rotation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace sdfwb::program {

glm::dmat3 rotationFromAngles(const glm::dvec3& degrees) {
    glm::dvec3 r = glm::radians(degrees);
    double cx = std::cos(r.x), sx = std::sin(r.x);
    double cy = std::cos(r.y), sy = std::sin(r.y);
    double cz = std::cos(r.z), sz = std::sin(r.z);
    // GLM matrices are column-major: dmat3(col0, col1, col2).
    glm::dmat3 rx(glm::dvec3(1, 0, 0), glm::dvec3(0, cx, sx), glm::dvec3(0, -sx, cx));
    glm::dmat3 ry(glm::dvec3(cy, 0, -sy), glm::dvec3(0, 1, 0), glm::dvec3(sy, 0, cy));
    glm::dmat3 rz(glm::dvec3(cz, sz, 0), glm::dvec3(-sz, cz, 0), glm::dvec3(0, 0, 1));
    return rz * ry * rx;
}

namespace {
// `angle` plus the multiple of 360 that brings it nearest to `near` (degrees).
double unwrapped(double angle, double near) { return angle + 360.0 * std::round((near - angle) / 360.0); }
}  // namespace

glm::dvec3 anglesFromRotation(const glm::dmat3& r, const glm::dvec3& near) {
    // Rz*Ry*Rx has row 2 = (-sy, cy sx, cy cx) and column 0 = (cy cz, cy sz, -sy); m[column][row]
    double sy = std::clamp(-r[0][2], -1.0, 1.0);
    double y = glm::degrees(std::asin(sy));
    if (std::abs(sy) > 1.0 - 1e-12) {
        // gimbal lock: R = Rz(z -+ x) Ry(+-90); keep x, put the rest in z
        double sum = glm::degrees(std::atan2(-r[1][0], r[1][1]));
        double z = sy > 0 ? sum + near.x : sum - near.x;
        return {near.x, unwrapped(y, near.y), unwrapped(z, near.z)};
    }
    glm::dvec3 first(glm::degrees(std::atan2(r[1][2], r[2][2])), y, glm::degrees(std::atan2(r[0][1], r[0][0])));
    glm::dvec3 second(first.x + 180.0, 180.0 - y, first.z + 180.0);
    glm::dvec3 best;
    double bestDistance = INFINITY;
    for (glm::dvec3 candidate : {first, second}) {
        for (int i = 0; i < 3; ++i) candidate[i] = unwrapped(candidate[i], near[i]);
        double distance = glm::length(candidate - near);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

}  // namespace sdfwb::program
