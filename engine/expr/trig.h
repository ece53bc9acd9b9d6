#pragma once
// Exact conversion of trigonometric parametrizations to rational ones, for
// implicitization: the torus, the Moebius strip, the cross-cap.
//
// sin, cos and tan may take any rational linear combination of parameters
// without constant term (u, 2*v, v/2, u - 3*v). For each parameter phi inside
// them, phi = m*psi with m = gcd(numerators)/lcm(denominators) of its
// coefficients, so every multiple of psi is an integer and coprime; multiple
// angles expand exactly through (cos psi + i sin psi)^n, sums through the
// addition formulas (the same product). Then each psi is replaced by:
//   HalfAngle:      cos psi = (1 - t^2)/(1 + t^2), sin psi = 2t/(1 + t^2), one new parameter t;
//   CosSinRelation: two new parameters c = cos psi, s = sin psi and the relation c^2 + s^2 - 1.
// New parameters get internal names (algebra::internalVariableName) that no
// user identifier can equal. A parameter used inside sin/cos/tan must not
// appear outside them: the result would not be algebraic.

#include <string>
#include <vector>

#include "algebra/implicitization.h"
#include "expr/formula.h"

namespace sdfwb::expr {

enum class TrigStrategy { HalfAngle, CosSinRelation };

// How one user parameter became new ones: parameter = scale * psi, and psi
// is 2*atan(t) (HalfAngle) or the angle of (c, s) (CosSinRelation).
struct AngleSubstitution {
  std::string parameter;
  mpq_class scale;
  std::vector<std::string> replacements;  // {t} or {c, s}
};

struct TrigConversion {
  // The input of algebra::implicitize. Its parameters are the user's
  // parameters that occur outside sin/cos/tan, in order of first use, with
  // each angle replaced in place by its new parameters; its polynomials share
  // one ring of those parameters; relations are empty for HalfAngle.
  algebra::RationalParametrization parametrization;
  std::vector<AngleSubstitution> angles;
};

// Throws Error at the offending column: a trigonometric argument that is not
// a rational linear form ("column 9: the argument of 'cos' must be ..."), a
// parameter used both inside and outside sin/cos/tan, or a non-rational
// function such as sqrt.
TrigConversion toRationalParametrization(const ParametricEquations& equations, TrigStrategy strategy);

// compileParametricEquations then toRationalParametrization: parametric text
// such as "x = u*v; y = v; z = u^2" to what algebra::implicitize takes. The
// default is CosSinRelation: measured with tests/bench/algebra_bench (Nov
// 2026), it implicitizes the torus, Moebius strip and cross-cap in under
// 1 ms each, against 1.1, 12 and 71 ms with HalfAngle, whose denominators
// grow with every angle.
TrigConversion parseParametrization(std::string_view source,
                                    TrigStrategy strategy = TrigStrategy::CosSinRelation);

// The largest multiple |n| of an angle after the substitution (cos(n*psi)
// expands to degree n).
constexpr long kMaxAngleMultiple = 100;

}  // namespace sdfwb::expr
