#pragma once
// Polynomial systems shared by the algebra tests and the benchmark: classic
// benchmark families (Katsura, cyclic) and small textbook systems.

#include "algebra/ideal.h"
#include "algebra/implicitization.h"

#include <string>
#include <vector>

namespace sdfwb::algebra::testing {

struct NamedSystem {
  std::string name;
  Ideal ideal;
};

/// Katsura-n: n+1 unknowns u0..un, zero-dimensional with 2^n solutions.
Ideal katsura(int n, const MonomialOrder& order = MonomialOrder::degrevlex());
/// Cyclic-n roots.
Ideal cyclic(int n, const MonomialOrder& order = MonomialOrder::degrevlex());

/// Small systems with several orders, fast enough for unit tests.
std::vector<NamedSystem> smallSystems();

struct NamedParametrization {
  std::string name;
  RationalParametrization parametrization;
};

/// Classic surfaces: Cox-Little-O'Shea examples and trigonometric surfaces
/// (torus, cross-cap, Moebius strip, Dupin cyclide), the trigonometric ones
/// both with c = cos, s = sin and c^2 + s^2 = 1 ("/cs") and with the
/// half-angle substitution ("/half-angle").
std::vector<NamedParametrization> classicParametrizations();

/// CAD-style patches (example_patches.cpp), with fixed pseudo-random small
/// integer control points and weights: height patches z = p(u,v)/q(u,v),
/// Bezier patches of bidegree (m, n) (implicit degree 2mn), polynomial and
/// rational, a quadratic patch with 9-digit coefficients, a rational
/// Steiner patch and a bilinear rational patch. `maxDegree` leaves out the
/// patches whose implicit degree exceeds it (the bicubic's is 18).
std::vector<NamedParametrization> patchParametrizations(unsigned maxDegree = 18);

/// A Bezier patch of bidegree (m, n) whose control points (and weights,
/// when `rational`) come from `seed`: for random tests.
RationalParametrization bezierPatch(unsigned m, unsigned n, bool rational, unsigned seed);

/// The polynomials as the formula language prints them, for comparisons.
std::vector<std::string> strings(const std::vector<Polynomial>& polys);

}  // namespace sdfwb::algebra::testing
