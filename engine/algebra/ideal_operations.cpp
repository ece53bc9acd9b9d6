#include "algebra/ideal_operations.h"

#include "algebra/gb_elimination.h"
#include "algebra/gb_modular.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace sdfwb::algebra {

namespace {

void checkSameRing(const Ideal& i, const Ideal& j, const char* operation) {
  if (!(*i.ring() == *j.ring())) throw std::invalid_argument(std::string(operation) + " of ideals of different rings");
}

Decision decisionFrom(const GroebnerResult& result, bool value) {
  Decision d;
  d.status = result.status;
  d.message = result.message;
  d.value = result.ok() && value;
  d.seconds = result.seconds;
  return d;
}

// The ring's variables with `extra` prepended and a block order that ranks
// them above the ring's own variables (ordered as before when possible).
RingPtr withEliminatedFirst(const Ring& ring, const std::vector<std::string>& extra) {
  std::vector<std::string> names = extra;
  names.insert(names.end(), ring.variables().begin(), ring.variables().end());
  return Ring::make(names, MonomialOrder::elimination(extra.size(), MonomialOrder::degrevlex(), ring.order()));
}

}  // namespace

Ideal sum(const Ideal& i, const Ideal& j) {
  checkSameRing(i, j, "sum");
  std::vector<Polynomial> generators = i.generators();
  generators.insert(generators.end(), j.generators().begin(), j.generators().end());
  return Ideal(i.ring(), generators);
}

Ideal product(const Ideal& i, const Ideal& j) {
  checkSameRing(i, j, "product");
  std::vector<Polynomial> generators;
  for (const Polynomial& f : i.generators()) {
    for (const Polynomial& g : j.generators()) generators.push_back(f * g);
  }
  return Ideal(i.ring(), generators);
}

Decision contains(const Ideal& ideal, const Polynomial& f, const GroebnerOptions& options) {
  GroebnerResult basis = groebnerBasis(ideal, options);
  if (!basis.ok()) return decisionFrom(basis, false);
  return decisionFrom(basis, normalForm(f.inRing(ideal.ring()), basis.basis).isZero());
}

Decision radicalContains(const Ideal& ideal, const Polynomial& f, const GroebnerOptions& options) {
  const std::string y = internalVariableName("y", ideal.ring()->variables());
  RingPtr ring = withEliminatedFirst(*ideal.ring(), {y});
  std::vector<Polynomial> generators;
  for (const Polynomial& g : ideal.generators()) generators.push_back(g.inRing(ring));
  generators.push_back(1 - f.inRing(ring) * ring->var(y));
  GroebnerResult basis = groebnerBasis(Ideal(ring, generators), options);
  return decisionFrom(basis, basis.basis.size() == 1 && basis.basis.front().isConstant());
}

GroebnerResult intersection(const Ideal& i, const Ideal& j, const GroebnerOptions& options) {
  checkSameRing(i, j, "intersection");
  const std::string t = internalVariableName("t", i.ring()->variables());
  RingPtr ring = withEliminatedFirst(*i.ring(), {t});
  Polynomial tv = ring->var(t);
  std::vector<Polynomial> generators;
  for (const Polynomial& f : i.generators()) generators.push_back(tv * f.inRing(ring));
  for (const Polynomial& g : j.generators()) generators.push_back((1 - tv) * g.inRing(ring));
  GroebnerResult result = groebnerBasis(Ideal(ring, generators), options);
  std::vector<Polynomial> kept;
  for (const Polynomial& g : result.basis) {
    if (!g.containsVariable(0)) kept.push_back(g.inRing(i.ring()));
  }
  result.basis = std::move(kept);
  return result;
}

GroebnerResult eliminate(const Ideal& ideal, const std::vector<std::string>& variables,
                         const GroebnerOptions& options, const MonomialOrder& remainingOrder) {
  const Ring& ring = *ideal.ring();
  for (const std::string& v : variables) {
    if (!ring.indexOf(v)) throw std::invalid_argument("eliminate: unknown variable '" + v + "'");
  }
  std::vector<std::string> eliminated, remaining;
  for (const std::string& v : ring.variables()) {
    bool drop = std::find(variables.begin(), variables.end(), v) != variables.end();
    (drop ? eliminated : remaining).push_back(v);
  }
  RingPtr remainingRing = Ring::make(remaining, remainingOrder);
  if (options.method != GroebnerMethod::Rational) {
    // Modular, lifting only the elimination ideal; membership of the lifted
    // polynomials is decided by a degrevlex basis of the whole ideal,
    // usually far cheaper than a basis in an elimination order.
    GroebnerResult result;
    result.method = "modular+elimination";
    BudgetMonitor monitor(options.budget);
    RingPtr degrevlex = ideal.ring()->withOrder(MonomialOrder::degrevlex());
    std::optional<std::vector<Polynomial>> whole;
    GroebnerStats wholeStats;
    auto contains = [&](const Polynomial& f) {
      if (!whole) {
        std::vector<Polynomial> generators;
        for (const Polynomial& g : ideal.generators()) generators.push_back(g.inRing(degrevlex));
        whole = gb::modularGroebner(generators, degrevlex, monitor, wholeStats);
      }
      return normalForm(f.inRing(degrevlex), *whole).isZero();
    };
    runWithinBudget(result, monitor, [&] {
      result.basis = gb::modularElimination(ideal, eliminated, remainingRing, contains, monitor, result.stats);
    });
    if (!result.ok()) result.basis.clear();
    return result;
  }
  std::vector<std::string> names = eliminated;
  names.insert(names.end(), remaining.begin(), remaining.end());
  // Elimination order: the degree in the eliminated variables first, then
  // degrevlex on them and remainingOrder on the rest. (A weight vector is
  // far cheaper than the block order (degrevlex, remainingOrder).)
  std::vector<std::int64_t> weights(names.size(), 0);
  std::fill(weights.begin(), weights.begin() + static_cast<std::ptrdiff_t>(eliminated.size()), 1);
  RingPtr block = Ring::make(
      names, MonomialOrder::weighted(weights, MonomialOrder::elimination(eliminated.size(), MonomialOrder::degrevlex(),
                                                                         remainingOrder)));
  GroebnerResult result = groebnerBasis(Ideal(block, ideal.generators()), options);
  std::vector<Polynomial> kept;
  for (const Polynomial& g : result.basis) {
    bool free = true;
    for (std::size_t v = 0; v < eliminated.size() && free; ++v) free = !g.containsVariable(v);
    if (free) kept.push_back(g.inRing(remainingRing));
  }
  // The basis is sorted by increasing leading monomial in the elimination
  // order, which agrees with remainingOrder on these polynomials.
  result.basis = std::move(kept);
  return result;
}

}  // namespace sdfwb::algebra
