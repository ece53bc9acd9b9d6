#pragma once
// Trigonometric parametrizations kept as cos/sin variables (c, s with the
// relation c^2 + s^2 - 1) made rational by the circle's parametrization
//   c = (1 - t^2) / (1 + t^2),   s = 2 t / (1 + t^2),
// exact and general: the image of the circle minus (-1, 0) is dense in the
// circle, so the closure of the image, the implicit equation, is unchanged.
// Without the relation, interpolation applies (implicit_interpolation.h).

#include "algebra/implicitization.h"

#include <optional>

namespace sdfwb::algebra {

/// `p` with every pair of parameters (c, s) bound by a relation that is a
/// constant times c^2 + s^2 - 1 replaced by one new parameter t as above
/// (named so it collides with no parameter or coordinate), that relation
/// dropped and the others rewritten; nullopt when no relation has that shape.
std::optional<RationalParametrization> rationalCircles(const RationalParametrization& p);

}  // namespace sdfwb::algebra
