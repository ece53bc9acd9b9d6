#pragma once
// Internal: homogenization with a new smallest variable h.
//
// For an order > on the old variables, a Groebner basis of the homogenized
// ideal for the order "total degree, then > on the old variables, then h"
// becomes a Groebner basis of the ideal for > when h is set to 1
// (Kreuzer and Robbiano, Computational Commutative Algebra 2, section 4.3).
// Homogeneous computations are graded, which keeps Buchberger from
// wandering through high degrees under orders that are not degree orders.

#include "algebra/polynomial.h"

namespace sdfwb::algebra::gb {

/// The ring's variables plus a fresh last variable, ordered as above.
RingPtr homogenizedRing(const Ring& ring);
/// f with every term multiplied by h^(deg f - deg term), in `homogeneous`.
Polynomial homogenize(const Polynomial& f, const RingPtr& homogeneous);
/// f with h = 1, in `ring` (the ring without h).
Polynomial dehomogenize(const Polynomial& f, const RingPtr& ring);

}  // namespace sdfwb::algebra::gb
