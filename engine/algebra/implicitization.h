#pragma once
// Implicitization: the implicit equations of a curve or surface given by a
// rational parametrization, by elimination (Cox-Little-O'Shea 3.3):
//
// - polynomial x_i = f_i(t): eliminate t from <x_i - f_i> (Theorem 1.7);
// - rational x_i = f_i/q_i: eliminate y and t from <q_i*x_i - f_i, 1 - q*y>
//   (Theorem 1.8), with q the lcm of the reduced denominators (the same
//   elimination ideal as with their product, at a fraction of the cost);
// - relations among the parameters (c^2 + s^2 - 1 when c = cos(phi) and
//   s = sin(phi) are kept as variables) are added to the ideal.
//
// The auxiliary y gets an internal name no user identifier can spell
// (internalVariableName), so it never collides with a parameter.

#include "algebra/elimination_order.h"
#include "algebra/groebner.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::algebra {

struct RationalParametrization {
  /// Parameter names (u, v, t, ...; also the c/s or half-angle variables of
  /// a converted trigonometric formula).
  std::vector<std::string> parameters;
  /// Coordinate names, in the order that ranks them (x > y > z).
  std::vector<std::string> coordinates;
  /// coordinates[i] = numerators[i] / denominators[i]. Polynomials of any ring
  /// whose variables include every parameter that occurs; only parameters
  /// may occur. An empty `denominators` means all 1.
  std::vector<Polynomial> numerators;
  std::vector<Polynomial> denominators;
  /// Polynomials in the parameters that vanish on the parameter domain,
  /// e.g. c^2 + s^2 - 1.
  std::vector<Polynomial> relations;
};

enum class DenominatorStrategy {
  Lcm,      // q = lcm of the reduced denominators (the default)
  Product,  // q = product of the denominators as given (for comparison only)
};

/// The order of the coordinates under `order` (degrevlex, deglex or lex).
MonomialOrder coordinateOrder(EliminationOrder order);

struct ImplicitizationOptions {
  GroebnerOptions groebner;  // budget and method
  DenominatorStrategy denominator = DenominatorStrategy::Lcm;
  EliminationOrder order = EliminationOrder::BlockDegrevlex;
  /// Solve for the parameters that occur linearly with a constant
  /// coefficient in an equation and substitute them before any basis
  /// (substituteLinearParameters).
  bool substituteLinear = true;
  /// A hypersurface (one parameter fewer than coordinates, no relations) by
  /// interpolation modulo primes (implicit_interpolation.h), unless the
  /// method is GroebnerMethod::Rational or the order is lex (the textbook's
  /// elimination, kept for comparison). Elimination where it does not apply.
  bool interpolate = true;
  /// Where interpolation applies to a polynomial parametrization,
  /// elimination first within a share of interpolation's expected cost
  /// (implicitize). False: interpolation straight away.
  bool eliminationTrial = true;
};

struct ImplicitizationResult {
  Status status = Status::Completed;
  std::string message;  // empty when completed, else "gave up after ..."
  /// The ring of the coordinates, coordinates[0] largest, ordered by
  /// coordinateOrder(options.order); degrevlex when there is exactly one
  /// generator (which every order gives, up to a factor).
  RingPtr ring;
  /// Reduced Groebner basis of the elimination ideal in `ring`, each
  /// generator scaled to a primitive integer polynomial with positive leading
  /// coefficient. Exactly one generator: the implicit equation. Several: the
  /// variety is cut out by all of them (e.g. a space curve). None: the image
  /// is dense.
  std::vector<Polynomial> generators;
  GroebnerStats stats;
  double seconds = 0;
  /// What ran: "interpolation", "substitution" (every parameter solved for;
  /// a basis of what is left), "substitution+elimination", "elimination".
  std::string method;

  bool ok() const { return status == Status::Completed; }
  /// The largest total degree among the generators.
  std::uint64_t degree() const;
  /// The number of terms, summed over the generators.
  std::size_t termCount() const;
};

/// The ideal whose elimination gives the implicit equations, and the
/// variables to eliminate (the auxiliary y of Theorem 1.8 first, if any, then
/// the parameters); its ring lists those variables first, then the
/// coordinates, with the elimination order. Exposed so the ideal can be shown
/// or handed to another system.
struct EliminationProblem {
  Ideal ideal;
  std::vector<std::string> eliminated;
};
EliminationProblem implicitizationIdeal(const RationalParametrization& parametrization,
                                         DenominatorStrategy denominator = DenominatorStrategy::Lcm);

/// The same elimination ideal with fewer variables: while a generator is
/// a*t + r with t an eliminated variable, a a nonzero constant and r free of
/// t (x - u, y - v, 2*u + v^2 - x, or (1 + v^2)*x - u of a fraction), t is
/// replaced by -r/a everywhere and that generator dropped. The ring keeps
/// the eliminated variables left, then the others, with the elimination
/// order (degrevlex when none is left).
EliminationProblem substituteLinearParameters(const EliminationProblem& problem);

/// Throws std::invalid_argument with one clear line for malformed input
/// (counts differ, a zero denominator, a coordinate named like a parameter,
/// a variable that is not a parameter).
ImplicitizationResult implicitize(const RationalParametrization& parametrization,
                                  const ImplicitizationOptions& options = {});

/// The parametrization over one denominator, in the ring of the parameters
/// (degrevlex): coordinate i is scaled[i] / common, with common the lcm of
/// the reduced, monic denominators. (common : scaled[0] : ...) are the
/// homogeneous coordinates of the image point.
struct ClearedParametrization {
  RingPtr ring;
  Polynomial common;
  std::vector<Polynomial> scaled;
  std::vector<Polynomial> relations;
};
ClearedParametrization clearDenominators(const RationalParametrization& parametrization);

/// F evaluated on the parametrization, with denominators cleared and reduced
/// modulo the relations: zero exactly when F vanishes on the parametrized set
/// (F is a polynomial in the coordinates, by name). The result lives in the
/// ring of the parameters (degrevlex).
Polynomial substituteParametrization(const Polynomial& f, const RationalParametrization& parametrization);

}  // namespace sdfwb::algebra
