#pragma once
// The rotate node's matrix: angles about x, y, z in degrees, applied in that
// order to the shape (R = Rz * Ry * Rx); points are mapped by its inverse.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace sdfwb::program {

glm::dmat3 rotationFromAngles(const glm::dvec3& degrees);
// The angles of a rotation matrix (the inverse of rotationFromAngles): of
// the two solutions (x, y, z) and (x + 180, 180 - y, z + 180), each angle
// taken modulo 360, the one nearest to `near`, so that a handle turning a
// node past y = 90 or x = 180 goes on smoothly instead of jumping. At
// y = +-90 only x - z (or x + z) is defined; x stays at near.x.
glm::dvec3 anglesFromRotation(const glm::dmat3& rotation, const glm::dvec3& near = glm::dvec3(0.0));

}  // namespace sdfwb::program
