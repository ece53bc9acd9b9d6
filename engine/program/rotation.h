#pragma once
// The rotate node's matrix: angles about x, y, z in degrees, applied in that
// order to the shape (R = Rz * Ry * Rx); points are mapped by its inverse.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace sdfwb::program {

glm::dmat3 rotationFromAngles(const glm::dvec3& degrees);

}  // namespace sdfwb::program
