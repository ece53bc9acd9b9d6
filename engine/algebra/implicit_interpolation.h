#pragma once
// Implicitization of a rational hypersurface by interpolation: linear
// algebra modulo word-size primes instead of a Groebner basis.
//
// With one common denominator, x_i = X_i(t) / W(t), the image of the
// parametrization (n coordinates, n - 1 parameters) is a hypersurface whose
// projective closure has one irreducible equation F(w, x_1, ..., x_n),
// homogeneous of some degree e. F's unknown coefficients on the C(e+n, n)
// monomials of degree e are a vector in the nullspace of the matrix of those
// monomials evaluated at (W, X_1, ..., X_n)(t) for many points t. Modulo a
// prime p:
//
//  1. the degree search tries e = 1, 2, ... up to a bound from the
//     parametrization (Bezout: deg(W, X)^(n-1); multihomogeneous:
//     (n-1)! * prod of the degrees in each parameter) and stops at the first
//     nonzero nullspace. F mod p lies in the nullspace at deg F, so the
//     search never stops later than deg F; it may stop earlier only for an
//     unlucky choice of points, which the next primes expose;
//  2. the nullspace at e has dimension 1 (F's multiples of degree e are F's
//     scalar multiples); a larger one means the image is not a hypersurface
//     or the prime or points are unlucky: the prime is skipped, and a first
//     prime whose nullspace stays larger makes interpolation not apply;
//  3. vectors normalized to 1 at their last nonzero coordinate are combined
//     by Chinese remaindering and rational reconstruction (FLINT's fmpz),
//     adding primes until the reconstruction agrees with a fresh prime;
//  4. the candidate is checked exactly: F(W(t), X(t)) has degree at most
//     e * m_j in parameter t_j (m_j: the largest degree of W, X in t_j), so
//     it is the zero polynomial when it vanishes, in exact integer
//     arithmetic, on a grid of (e * m_j + 1) integers per parameter. A
//     candidate that fails takes more primes.
//
// Step 4 proves that F vanishes on the image, so the irreducible equation G
// divides F; step 1 found deg F <= deg G; hence F = G up to a constant. The
// answer is exact, not probabilistic.
//
// The matrices are dense: nmod_mat (FLINT 2.9) reduces them asymptotically
// fast. Primes after the first run in parallel, one per hardware thread.

#include "algebra/budget.h"
#include "algebra/groebner_stats.h"
#include "algebra/implicitization.h"

#include <cstddef>
#include <optional>

namespace sdfwb::algebra {

/// The largest number of unknown coefficients (monomials of the degree
/// tried) interpolation takes on: 2024 is degree 21 for a surface. One
/// matrix then needs about 70 MB and a second modulo a prime.
inline constexpr std::size_t kMaxInterpolationMonomials = 2024;

/// What interpolation is expected to cost, in multiplications modulo a
/// prime: a few dense nullspaces (the degree search, then the primes of the
/// reconstruction) of the size at the degree bound (or at
/// kMaxInterpolationMonomials, where the search stops). Nullopt when
/// interpolation does not apply to the shape of `p` (relations, parameter
/// count). Cheap: no matrix is built.
std::optional<double> interpolationCost(const RationalParametrization& p);

/// The implicit equation of `p` in `coordinates` (a ring of p's coordinates),
/// primitive with a positive leading coefficient, verified exactly; nullopt
/// when interpolation does not apply: relations among the parameters, a
/// parameter count other than coordinates - 1, an image that is not a
/// hypersurface, or more monomials than kMaxInterpolationMonomials before
/// the degree is found. Reports stages "interpolation" and "verification" to
/// the monitor; throws BudgetExceeded.
std::optional<Polynomial> implicitizeByInterpolation(const RationalParametrization& p, const RingPtr& coordinates,
                                                       BudgetMonitor& monitor, GroebnerStats& stats);

}  // namespace sdfwb::algebra
