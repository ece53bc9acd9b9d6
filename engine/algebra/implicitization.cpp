#include "algebra/implicitization.h"

#include "algebra/flint_polynomial.h"
#include "algebra/gb_elimination.h"
#include "algebra/implicit_interpolation.h"
#include "algebra/ideal_operations.h"
#include "algebra/polynomial_gcd.h"
#include "algebra/rational_circles.h"

#include <algorithm>
#include <stdexcept>

namespace sdfwb::algebra {

namespace {

// The share of interpolation's expected cost (multiplications modulo a
// prime) that elimination may spend first, in the monitor's work units
// (term operations and pair bookkeeping). Measured on the benchmark's
// cases (docs/algebra-benchmark.md), a unit costs about as much as 500 of
// FLINT's dense multiplications, so a failed trial takes at most about half
// the interpolation's expected time.
constexpr double kEliminationTrialShare = 1.0 / 1024;

struct Fractions {
  RingPtr ring;  // parameters, degrevlex
  std::vector<Polynomial> numerators, denominators, relations;
};

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Checks the input and moves everything into the ring of the parameters.
Fractions prepare(const RationalParametrization& p) {
  const std::size_t n = p.coordinates.size();
  if (n == 0) throw std::invalid_argument("implicitize: no coordinates");
  if (p.numerators.size() != n) {
    throw std::invalid_argument("implicitize: " + std::to_string(p.numerators.size()) + " numerators for " +
                                std::to_string(n) + " coordinates");
  }
  if (!p.denominators.empty() && p.denominators.size() != n) {
    throw std::invalid_argument("implicitize: " + std::to_string(p.denominators.size()) + " denominators for " +
                                std::to_string(n) + " coordinates");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (contains(p.parameters, p.coordinates[i])) {
      throw std::invalid_argument("implicitize: '" + p.coordinates[i] + "' is both a coordinate and a parameter");
    }
    if (std::count(p.coordinates.begin(), p.coordinates.end(), p.coordinates[i]) > 1) {
      throw std::invalid_argument("implicitize: coordinate '" + p.coordinates[i] + "' given twice");
    }
  }
  Fractions f;
  f.ring = Ring::make(p.parameters, MonomialOrder::degrevlex());
  auto move = [&](const Polynomial& q, const std::string& what) {
    try {
      return q.inRing(f.ring);
    } catch (const std::invalid_argument&) {
      for (std::size_t v = 0; v < q.ring()->size(); ++v) {
        if (q.containsVariable(v) && !f.ring->indexOf(q.ring()->variable(v))) {
          throw std::invalid_argument("implicitize: " + what + " uses '" + q.ring()->variable(v) +
                                      "', which is not a parameter");
        }
      }
      throw;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    f.numerators.push_back(move(p.numerators[i], "the formula for " + p.coordinates[i]));
    f.denominators.push_back(p.denominators.empty() ? f.ring->one()
                                                    : move(p.denominators[i], "the formula for " + p.coordinates[i]));
    if (f.denominators.back().isZero()) {
      throw std::invalid_argument("implicitize: the denominator for " + p.coordinates[i] + " is zero");
    }
  }
  for (const Polynomial& r : p.relations) f.relations.push_back(move(r, "a relation"));
  return f;
}

// Cancels common factors and makes every denominator monic.
void reduceFractions(Fractions& f) {
  for (std::size_t i = 0; i < f.numerators.size(); ++i) {
    Polynomial& num = f.numerators[i];
    Polynomial& den = f.denominators[i];
    Polynomial g = gcd(num, den);
    if (!g.isConstant()) {
      num = *flint::divideExact(num, g);
      den = *flint::divideExact(den, g);
    }
    Rational lc = den.leadingCoefficient();
    num /= lc;
    den /= lc;
  }
}


// The lex basis of the whole ideal, of which the elements free of the
// eliminated variables are the lex basis of the elimination ideal.
GroebnerResult lexElimination(const EliminationProblem& problem, const RingPtr& coordinates,
                               const GroebnerOptions& options) {
  RingPtr lex = Ring::make(problem.ideal.ring()->variables(), MonomialOrder::lex());
  std::vector<Polynomial> generators;
  for (const Polynomial& g : problem.ideal.generators()) generators.push_back(g.inRing(lex));
  GroebnerResult result = groebnerBasis(Ideal(lex, generators), options);
  std::vector<Polynomial> kept;
  for (const Polynomial& g : result.basis) {
    bool free = true;
    for (std::size_t v = 0; v < problem.eliminated.size(); ++v) free = free && !g.containsVariable(v);
    if (free) kept.push_back(g.inRing(coordinates));
  }
  result.basis = std::move(kept);
  return result;
}

}  // namespace

EliminationProblem implicitizationIdeal(const RationalParametrization& p, DenominatorStrategy denominator) {
  Fractions f = prepare(p);
  if (denominator == DenominatorStrategy::Lcm) reduceFractions(f);

  // q: lcm of the reduced denominators (or their product).
  Polynomial q = f.ring->one();
  for (const Polynomial& den : f.denominators) {
    if (den.isConstant()) continue;
    q = denominator == DenominatorStrategy::Lcm ? lcm(q, den) : q * den;
  }

  std::vector<std::string> taken = p.parameters;
  taken.insert(taken.end(), p.coordinates.begin(), p.coordinates.end());
  std::vector<std::string> eliminated;
  if (!q.isConstant()) eliminated.push_back(internalVariableName("y", taken));
  eliminated.insert(eliminated.end(), p.parameters.begin(), p.parameters.end());
  std::vector<std::string> names = eliminated;
  names.insert(names.end(), p.coordinates.begin(), p.coordinates.end());
  RingPtr ring = Ring::make(names, MonomialOrder::elimination(eliminated.size()));

  std::vector<Polynomial> generators;
  for (std::size_t i = 0; i < p.coordinates.size(); ++i) {
    generators.push_back(f.denominators[i].inRing(ring) * ring->var(p.coordinates[i]) - f.numerators[i].inRing(ring));
  }
  if (!q.isConstant()) generators.push_back(1 - q.inRing(ring) * ring->var(eliminated.front()));
  for (const Polynomial& r : f.relations) generators.push_back(r.inRing(ring));
  return EliminationProblem{Ideal(ring, generators), eliminated};
}

MonomialOrder coordinateOrder(EliminationOrder order) {
  switch (order) {
    case EliminationOrder::BlockDegrevlex: return MonomialOrder::degrevlex();
    case EliminationOrder::BlockDeglex: return MonomialOrder::deglex();
    case EliminationOrder::BlockLex:
    case EliminationOrder::Lex: return MonomialOrder::lex();
  }
  throw std::invalid_argument("coordinate_order: unknown elimination order");
}

std::uint64_t ImplicitizationResult::degree() const {
  std::uint64_t degree = 0;
  for (const Polynomial& g : generators) degree = std::max(degree, g.totalDegree());
  return degree;
}

std::size_t ImplicitizationResult::termCount() const {
  std::size_t terms = 0;
  for (const Polynomial& g : generators) terms += g.termCount();
  return terms;
}

namespace {

// g = a*t + r with a a nonzero constant and r free of t: -r/a, else nullopt.
std::optional<Polynomial> linearSolution(const Polynomial& g, std::size_t t) {
  if (g.degreeIn(t) != 1) return std::nullopt;
  std::optional<Rational> a;
  std::vector<Term> rest;
  for (const Term& term : g.terms()) {
    if (term.monomial[t] == 0) {
      rest.push_back(term);
    } else if (term.monomial.degree() == 1 && !a) {
      a = term.coefficient;
    } else {
      return std::nullopt;  // t times another variable: the coefficient of t is not constant
    }
  }
  if (!a) return std::nullopt;
  return Polynomial(g.ring(), std::move(rest)) / -*a;
}

// <g, 1 - q*y> (or <g>) eliminating y is the saturation <g> : q^oo, which is
// principal: g without the factors it shares with q. Nullopt for an ideal of
// another shape.
std::optional<Polynomial> principalSaturation(const EliminationProblem& problem) {
  if (problem.eliminated.size() > 1) return std::nullopt;
  const Ring& ring = *problem.ideal.ring();
  std::optional<Polynomial> g, q;
  for (const Polynomial& f : problem.ideal.generators()) {
    const std::optional<std::size_t> y =
        problem.eliminated.empty() ? std::nullopt : ring.indexOf(problem.eliminated.front());
    if (!y || !f.containsVariable(*y)) {
      if (g) return std::nullopt;
      g = f;
      continue;
    }
    if (q || f.degreeIn(*y) != 1) return std::nullopt;
    std::vector<Term> free, withY;
    for (const Term& t : f.terms()) {
      if (t.monomial[*y] == 0) {
        free.push_back(t);
      } else {
        Term reduced = t;
        reduced.monomial[*y] = 0;
        withY.push_back(std::move(reduced));
      }
    }
    if (!(Polynomial(f.ring(), std::move(free)) == ring.one())) return std::nullopt;
    q = -Polynomial(f.ring(), std::move(withY));
  }
  if (!g) return std::nullopt;
  if (q) {
    for (Polynomial d = gcd(*g, *q); !d.isConstant(); d = gcd(*g, *q)) g = *flint::divideExact(*g, d);
  }
  return g;
}

}  // namespace

EliminationProblem substituteLinearParameters(const EliminationProblem& problem) {
  const RingPtr& ring = problem.ideal.ring();
  std::vector<Polynomial> generators = problem.ideal.generators();
  std::vector<std::string> kept;
  for (const std::string& name : problem.eliminated) {
    const std::size_t t = *ring->indexOf(name);
    std::optional<Polynomial> value;
    auto solved = generators.begin();
    for (; solved != generators.end() && !(value = linearSolution(*solved, t)); ++solved) {
    }
    if (!value) {
      kept.push_back(name);
      continue;
    }
    generators.erase(solved);
    std::vector<Polynomial> values;
    for (std::size_t v = 0; v < ring->size(); ++v) values.push_back(v == t ? *value : ring->var(v));
    std::vector<Polynomial> substituted;
    for (const Polynomial& g : generators) {
      Polynomial h = substitute(g, values);
      if (!h.isZero()) substituted.push_back(std::move(h));
    }
    generators = std::move(substituted);
  }
  std::vector<std::string> names = kept;
  for (const std::string& name : ring->variables()) {
    if (!contains(problem.eliminated, name)) names.push_back(name);
  }
  RingPtr smaller = Ring::make(names, kept.empty() ? MonomialOrder::degrevlex() : MonomialOrder::elimination(kept.size()));
  std::vector<Polynomial> moved;
  for (const Polynomial& g : generators) moved.push_back(g.inRing(smaller));
  return EliminationProblem{Ideal(smaller, moved), kept};
}

namespace {

ImplicitizationResult implicitizeWith(const RationalParametrization& p, const ImplicitizationOptions& options,
                                       BudgetMonitor& monitor) {
  EliminationProblem problem = implicitizationIdeal(p, options.denominator);
  // The auxiliary variable of Theorem 1.8 comes first when there is one.
  const bool hasDenominator = problem.eliminated.size() > p.parameters.size();
  ImplicitizationResult result;
  result.ring = Ring::make(p.coordinates, coordinateOrder(options.order));
  const bool modular = options.groebner.method != GroebnerMethod::Rational;
  std::vector<Polynomial> generators;
  bool done = false, substituted = false;
  if (options.substituteLinear) {
    const std::size_t before = problem.eliminated.size();
    Progress progress;
    progress.stage = "substitution";
    runWithinBudget(result, monitor, [&] {
      monitor.check(progress);
      problem = substituteLinearParameters(problem);
    });
    if (!result.ok()) return result;
    substituted = problem.eliminated.size() < before;
  }
  // Every parameter solved for: what is left (at most the auxiliary y of
  // Theorem 1.8 to eliminate) is smaller than any interpolation.
  const bool parametersLeft = std::any_of(problem.eliminated.begin(), problem.eliminated.end(),
                                           [&](const std::string& name) { return contains(p.parameters, name); });
  const std::string eliminationMethod =
      !parametersLeft ? "substitution" : substituted ? "substitution+elimination" : "elimination";
  // A polynomial in the coordinates lies in the elimination ideal exactly
  // when it vanishes on the parametrization, which substitution decides
  // cheaply: the lifted equations are verified that way.
  // The textbook's lex order modulo p, lifting only the elimination part
  // (the lex basis of the whole ideal over Q is never needed).
  const std::optional<MonomialOrder> wholeOrder =
      options.order == EliminationOrder::Lex ? std::optional(MonomialOrder::lex()) : std::nullopt;
  auto modularElimination = [&] {
    auto vanishes = [&p](const Polynomial& f) { return substituteParametrization(f, p).isZero(); };
    generators = gb::modularElimination(problem.ideal, problem.eliminated, result.ring, vanishes, monitor,
                                         result.stats, wholeOrder);
  };
  const std::optional<double> interpolation =
      options.interpolate && modular && options.order != EliminationOrder::Lex && parametersLeft
          ? interpolationCost(p)
          : std::nullopt;
  if (interpolation && options.eliminationTrial && !hasDenominator) {
    // Interpolation solves dense systems in every monomial of the degree;
    // elimination works on the terms that occur, and is far cheaper when a
    // polynomial parametrization is sparse or one parameter is left. Neither
    // shows in a degree bound, so elimination runs first within a small
    // share of interpolation's expected cost (counted in term operations,
    // not time, so the choice does not depend on the load) and is abandoned
    // beyond. Not with a denominator: its auxiliary variable raises the
    // elimination's degrees by the denominator's, and elimination lost to
    // interpolation on every rational patch and half-angle surface measured
    // (docs/algebra-benchmark.md).
    monitor.limitWork(static_cast<std::uint64_t>(*interpolation * kEliminationTrialShare));
    try {
      runWithinBudget(result, monitor, modularElimination);
      done = true;
      result.method = eliminationMethod;
    } catch (const WorkLimitReached&) {
      generators.clear();
      result.stats = {};
    }
    monitor.limitWork(std::nullopt);
    if (!result.ok()) return result;
  }
  if (interpolation && !done) {
    runWithinBudget(result, monitor, [&] {
      if (std::optional<Polynomial> f = implicitizeByInterpolation(p, result.ring, monitor, result.stats)) {
        generators.push_back(std::move(*f));
        done = true;
      }
    });
    if (!result.ok()) return result;
    if (done) result.method = "interpolation";
  }
  if (!done && !parametersLeft) {
    if (std::optional<Polynomial> g = principalSaturation(problem)) {
      generators.push_back(g->inRing(result.ring));
      result.method = "substitution";
      done = true;
    }
  }
  if (!done && problem.eliminated.empty()) {
    GroebnerResult basis = groebnerBasis(Ideal(result.ring, problem.ideal.generators()), options.groebner);
    result.status = basis.status;
    result.message = basis.message;
    result.stats = basis.stats;
    generators = std::move(basis.basis);
    result.method = "substitution";
    done = true;
  }
  if (!done) result.method = eliminationMethod;
  if (!done && !modular) {
    GroebnerResult basis = options.order == EliminationOrder::Lex
                               ? lexElimination(problem, result.ring, options.groebner)
                               : eliminate(problem.ideal, problem.eliminated, options.groebner, result.ring->order());
    result.status = basis.status;
    result.message = basis.message;
    result.stats = basis.stats;
    generators = std::move(basis.basis);
  } else if (!done) {
    runWithinBudget(result, monitor, modularElimination);
  }
  result.seconds = monitor.elapsedSeconds();
  if (!result.ok()) return result;
  if (generators.size() == 1) {
    // One equation is the same under every order, so it is normalized and
    // printed under one: degrevlex.
    result.ring = Ring::make(p.coordinates, MonomialOrder::degrevlex());
    result.generators.push_back(generators.front().inRing(result.ring).primitive());
  } else {
    for (const Polynomial& g : generators) result.generators.push_back(g.inRing(result.ring).primitive());
  }
  return result;
}

}  // namespace

ImplicitizationResult implicitize(const RationalParametrization& p, const ImplicitizationOptions& options) {
  BudgetMonitor monitor(options.groebner.budget);
  // cos/sin variables: the circle's rational parametrization removes their
  // relations, and interpolation applies. As for polynomial
  // parametrizations, elimination of the given form runs first within a
  // share of interpolation's expected cost (the relations keep it small on
  // some surfaces, and the half-angle form's denominators raise degrees).
  // Under lex too: there the rational form is eliminated, not interpolated,
  // but it is the smaller problem in the same cases.
  const bool modular = options.groebner.method != GroebnerMethod::Rational;
  if (options.interpolate && modular && !p.relations.empty()) {
    prepare(p);  // the input's errors, before any conversion
    if (std::optional<RationalParametrization> rational = rationalCircles(p)) {
      if (std::optional<double> cost = interpolationCost(*rational); cost && options.eliminationTrial) {
        monitor.limitWork(static_cast<std::uint64_t>(*cost * kEliminationTrialShare));
        try {
          ImplicitizationResult result = implicitizeWith(p, options, monitor);
          monitor.limitWork(std::nullopt);
          return result;
        } catch (const WorkLimitReached&) {
          monitor.limitWork(std::nullopt);
        }
      }
      if (rational->relations.empty()) {
        ImplicitizationResult result = implicitizeWith(*rational, options, monitor);
        result.method = "half-angle+" + result.method;
        return result;
      }
    }
  }
  return implicitizeWith(p, options, monitor);
}

ClearedParametrization clearDenominators(const RationalParametrization& p) {
  // Reduced fractions: then every denominator divides the q of Theorem 1.8,
  // a unit modulo the ideal, which makes "substitutes to 0" equivalent to
  // membership in the elimination ideal (implicitize relies on it).
  Fractions f = prepare(p);
  reduceFractions(f);
  // x_i = n_i / d_i = (n_i * q/d_i) / q with q = lcm d_i.
  ClearedParametrization c{f.ring, f.ring->one(), {}, std::move(f.relations)};
  for (const Polynomial& den : f.denominators) c.common = lcm(c.common, den);
  for (std::size_t i = 0; i < f.numerators.size(); ++i) {
    c.scaled.push_back(flint::multiply(f.numerators[i], *flint::divideExact(c.common, f.denominators[i])));
  }
  return c;
}

Polynomial substituteParametrization(const Polynomial& implicit, const RationalParametrization& p) {
  // With e = deg F, q^e * F(scaled / q) is a polynomial.
  const ClearedParametrization f = clearDenominators(p);
  const Ring& source = *implicit.ring();
  std::vector<Polynomial> values;
  for (std::size_t v = 0; v < source.size(); ++v) {
    auto it = std::find(p.coordinates.begin(), p.coordinates.end(), source.variable(v));
    if (it != p.coordinates.end()) {
      values.push_back(f.scaled[static_cast<std::size_t>(it - p.coordinates.begin())]);
    } else if (implicit.containsVariable(v)) {
      throw std::invalid_argument("substitute_parametrization: '" + source.variable(v) + "' is not a coordinate");
    } else {
      values.push_back(f.ring->zero());
    }
  }
  const Polynomial sum = flint::substituteHomogeneous(implicit, values, f.common);
  if (f.relations.empty()) return sum;
  GroebnerResult relations = groebnerBasis(Ideal(f.ring, f.relations));
  return normalForm(sum, relations.basis);
}

}  // namespace sdfwb::algebra
