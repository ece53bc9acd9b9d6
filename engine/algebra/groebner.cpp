#include "algebra/groebner.h"

#include "algebra/gb_convert.h"
#include "algebra/gb_engine.h"
#include "algebra/gb_homogenize.h"
#include "algebra/gb_modular.h"

#include <algorithm>
#include <stdexcept>

namespace sdfwb::algebra {

namespace {

using IntegerEngine = gb::Engine<gb::IntegerDomain>;

void checkRing(const std::vector<Polynomial>& polys, const RingPtr& ring, const char* what) {
  for (const Polynomial& p : polys) {
    if (!(*p.ring() == *ring)) throw std::invalid_argument(std::string(what) + ": polynomials from different rings");
  }
}

// Orders whose first criterion is a positive degree (deglex, degrevlex,
// weighted with positive weights): the sugar strategy handles them well.
bool isDegreeOrder(const Ring& ring) {
  std::vector<std::vector<std::int64_t>> matrix = ring.order().matrix(ring.size());
  return !matrix.empty() &&
         std::all_of(matrix.front().begin(), matrix.front().end(), [](std::int64_t w) { return w > 0; });
}

// Reduced Groebner basis (monic, sorted) from a Groebner basis over Q.
std::vector<Polynomial> reduceBasis(const std::vector<Polynomial>& basis, const RingPtr& ring,
                                     BudgetMonitor& monitor) {
  const gb::Layout layout(*ring);
  const gb::IntegerDomain domain;
  IntegerEngine engine(layout, domain, monitor);
  std::vector<gb::IntPoly> packed;
  for (const Polynomial& g : basis) {
    if (!g.isZero()) packed.push_back(gb::toIntegerPoly(g, layout));
  }
  std::vector<Polynomial> out;
  for (const gb::IntPoly& g : engine.reduceBasis(std::move(packed))) {
    out.push_back(gb::toPolynomial(g, layout, ring, true));
  }
  return out;
}

// For orders that are not degree orders (lex, block and elimination
// orders), Buchberger on inhomogeneous input wanders through high degrees;
// the homogenized ideal is graded (see gb_homogenize.h).
std::vector<Polynomial> homogenizedGroebner(const Ideal& ideal, BudgetMonitor& monitor, GroebnerStats& stats) {
  RingPtr homogeneous = gb::homogenizedRing(*ideal.ring());
  std::vector<Polynomial> generators;
  for (const Polynomial& f : ideal.generators()) generators.push_back(gb::homogenize(f, homogeneous));
  std::vector<Polynomial> dehomogenized;
  for (const Polynomial& g : gb::modularGroebner(generators, homogeneous, monitor, stats)) {
    dehomogenized.push_back(gb::dehomogenize(g, ideal.ring()));
  }
  return reduceBasis(dehomogenized, ideal.ring(), monitor);
}

}  // namespace

GroebnerResult groebnerBasis(const Ideal& ideal, const GroebnerOptions& options) {
  GroebnerResult result;
  BudgetMonitor monitor(options.budget);
  if (options.method != GroebnerMethod::Rational) {
    runWithinBudget(result, monitor, [&] {
      const RingPtr& ring = ideal.ring();
      result.method = "modular";
      if (options.method == GroebnerMethod::Automatic && ring->order().kind() == MonomialOrder::Kind::Lex &&
          ring->size() > 1) {
        // Lex bases of zero-dimensional ideals: degrevlex, then FGLM.
        RingPtr degrevlex = ring->withOrder(MonomialOrder::degrevlex());
        std::vector<Polynomial> generators;
        for (const Polynomial& g : ideal.generators()) generators.push_back(g.inRing(degrevlex));
        gb::RecordedRun run;
        if (gb::zeroDimensionalModuloAPrime(generators, degrevlex, monitor, &run)) {
          std::vector<Polynomial> first =
              gb::modularGroebner(generators, degrevlex, monitor, result.stats, nullptr, &run);
          if (auto converted = gb::modularFglm(first, ring, monitor, result.stats)) {
            result.basis = std::move(*converted);
            result.method = "modular+fglm";
          }
        }
      }
      if (result.method == "modular" && options.method == GroebnerMethod::Automatic && !isDegreeOrder(*ring)) {
        result.basis = homogenizedGroebner(ideal, monitor, result.stats);
        result.method = "modular+homogenized";
      } else if (result.method == "modular") {
        result.basis = gb::modularGroebner(ideal.generators(), ring, monitor, result.stats);
      }
    });
    if (!result.ok()) result.basis.clear();
    return result;
  }
  result.method = "rational";
  const gb::Layout layout(*ideal.ring());
  const gb::IntegerDomain domain;
  IntegerEngine engine(layout, domain, monitor);
  runWithinBudget(result, monitor, [&] {
    std::vector<gb::IntPoly> input;
    for (const Polynomial& g : ideal.generators()) input.push_back(gb::toIntegerPoly(g, layout));
    std::vector<gb::IntPoly> basis = engine.groebner(std::move(input));
    for (const gb::IntPoly& g : basis) result.basis.push_back(gb::toPolynomial(g, layout, ideal.ring(), true));
  });
  if (!result.ok()) result.basis.clear();
  result.stats = engine.stats();
  return result;
}

GroebnerResult changeOrder(const std::vector<Polynomial>& basis, const RingPtr& target,
                            const GroebnerOptions& options) {
  GroebnerResult result;
  result.method = "modular+fglm";
  BudgetMonitor monitor(options.budget);
  runWithinBudget(result, monitor, [&] {
    std::optional<std::vector<Polynomial>> converted = gb::modularFglm(basis, target, monitor, result.stats);
    if (!converted) throw std::invalid_argument("change_order: the ideal is not zero-dimensional");
    result.basis = std::move(*converted);
  });
  return result;
}

Polynomial normalForm(const Polynomial& f, const std::vector<Polynomial>& basis) {
  checkRing(basis, f.ring(), "normal_form");
  const gb::Layout layout(*f.ring());
  const gb::IntegerDomain domain;
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  IntegerEngine engine(layout, domain, monitor);
  std::vector<gb::IntPoly> packed;
  for (const Polynomial& g : basis) packed.push_back(gb::toIntegerPoly(g, layout));
  engine.setBasis(std::move(packed));
  mpz_class denominator, scale;
  gb::IntPoly r = engine.normalForm(gb::toIntegerPoly(f, layout, &denominator), &scale);
  mpz_class divisor = denominator * scale;
  return gb::toPolynomial(r, layout, f.ring(), false, &divisor);
}

bool isReducedGroebnerBasis(const std::vector<Polynomial>& basis) {
  if (basis.empty()) return true;
  const RingPtr& ring = basis.front().ring();
  checkRing(basis, ring, "is_reduced_groebner_basis");
  for (std::size_t i = 0; i < basis.size(); ++i) {
    const Polynomial& g = basis[i];
    if (g.isZero() || g.leadingCoefficient() != 1) return false;
    if (i > 0 && ring->compare(basis[i - 1].leadingMonomial(), g.leadingMonomial()) >= 0) return false;
    for (const Polynomial& h : basis) {
      for (const Term& t : g.terms()) {
        if (&h != &g || &t != &g.terms().front()) {
          if (h.leadingMonomial().divides(t.monomial)) return false;
        }
      }
    }
  }
  for (std::size_t i = 0; i < basis.size(); ++i) {
    for (std::size_t j = i + 1; j < basis.size(); ++j) {
      const Monomial l = lcm(basis[i].leadingMonomial(), basis[j].leadingMonomial());
      Polynomial s = multiplyByTerm(basis[i], Rational(1), l / basis[i].leadingMonomial()) -
                     multiplyByTerm(basis[j], Rational(1), l / basis[j].leadingMonomial());
      if (!normalForm(s, basis).isZero()) return false;
    }
  }
  return true;
}

}  // namespace sdfwb::algebra
