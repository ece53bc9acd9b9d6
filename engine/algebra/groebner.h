#pragma once
// Reduced Groebner bases over Q.
//
//   auto ring = Ring::make({"x", "y"}, MonomialOrder::lex());
//   GroebnerResult r = groebnerBasis(Ideal(ring, {f1, f2}), {});
//   if (r.ok()) for (const Polynomial& g : r.basis) std::cout << g << "\n";
//   else std::cerr << r.message << "\n";  // "gave up after 10.0 s: ..."
//
// The reduced basis is unique: each element monic, no term of an element
// divisible by another element's leading monomial, elements sorted by
// increasing leading monomial. The zero ideal has the empty basis, the unit
// ideal the basis {1}.

#include "algebra/budget.h"
#include "algebra/groebner_stats.h"
#include "algebra/ideal.h"

#include <string>
#include <vector>

namespace sdfwb::algebra {

enum class GroebnerMethod {
  /// The fastest exact method we have: modular; for lex, first degrevlex and,
  /// if the ideal is zero-dimensional, FGLM to lex; for other orders that
  /// are not degree orders (block, elimination), via homogenization.
  Automatic,
  /// Bases modulo several primes, lifted to Q and verified over Q
  /// (see gb_modular.h for what the verification proves).
  Modular,
  /// Buchberger directly over Q with fraction-free integer arithmetic; every
  /// step exact, but intermediate coefficients can grow enormously.
  Rational,
};

struct GroebnerOptions {
  Budget budget;
  GroebnerMethod method = GroebnerMethod::Automatic;
};

struct GroebnerResult {
  Status status = Status::Completed;
  std::string message;             // empty when completed, else "gave up after ..."
  std::vector<Polynomial> basis;   // empty unless completed
  GroebnerStats stats;
  double seconds = 0;              // the computation's own wall-clock time
  std::string method;              // what ran: "modular", "modular+fglm", "modular+homogenized",
                                   // "modular+elimination" (eliminate), "rational"

  bool ok() const { return status == Status::Completed; }
};

/// Buchberger's algorithm (sugar selection, Gebauer-Moeller criteria) with
/// exact fraction-free arithmetic, in the ideal's ring and order.
GroebnerResult groebnerBasis(const Ideal& ideal, const GroebnerOptions& options = {});

/// The reduced basis in `target` (same variable names, another order) of the
/// zero-dimensional ideal whose reduced Groebner basis is `basis`, by FGLM.
/// Throws std::invalid_argument when the ideal is not zero-dimensional.
GroebnerResult changeOrder(const std::vector<Polynomial>& basis, const RingPtr& target,
                            const GroebnerOptions& options = {});

/// Normal form (remainder) of f by a Groebner basis of its ring, fully
/// reduced; it is the unique representative of f modulo the ideal. The result
/// is exact (not scaled).
Polynomial normalForm(const Polynomial& f, const std::vector<Polynomial>& groebnerBasis);

/// True if `basis` is a reduced Groebner basis in the sense above (every
/// S-polynomial reduces to zero, monic, no reducible term, sorted).
bool isReducedGroebnerBasis(const std::vector<Polynomial>& basis);

}  // namespace sdfwb::algebra
