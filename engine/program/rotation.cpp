#include "program/rotation.h"

#include <cmath>

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

}  // namespace sdfwb::program
