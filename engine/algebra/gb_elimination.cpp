#include "algebra/gb_elimination.h"

#include "algebra/gb_convert.h"
#include "algebra/gb_engine.h"
#include "algebra/gb_homogenize.h"
#include "algebra/gb_modular.h"

#include <algorithm>

namespace sdfwb::algebra::gb {

std::vector<Polynomial> modularElimination(const Ideal& ideal, const std::vector<std::string>& eliminated,
                                            const RingPtr& remaining,
                                            const std::function<bool(const Polynomial&)>& contains,
                                            BudgetMonitor& monitor, GroebnerStats& stats,
                                            const std::optional<MonomialOrder>& order) {
  const std::size_t k = eliminated.size();
  std::vector<std::string> names = eliminated;
  names.insert(names.end(), remaining->variables().begin(), remaining->variables().end());
  std::vector<std::int64_t> weights(names.size(), 0);
  std::fill(weights.begin(), weights.begin() + static_cast<std::ptrdiff_t>(k), 1);
  RingPtr base = Ring::make(
      names, order ? *order
                   : MonomialOrder::weighted(weights, MonomialOrder::elimination(k, MonomialOrder::degrevlex(),
                                                                                 remaining->order())));
  RingPtr homogeneous = homogenizedRing(*base);
  std::vector<Polynomial> generators;
  for (const Polynomial& f : ideal.generators()) generators.push_back(homogenize(f.inRing(base), homogeneous));

  const Layout from(*homogeneous);
  const Layout to(*remaining);
  LiftTarget target;
  target.ring = remaining;
  // Elements whose leading monomial is free of the eliminated variables lie
  // in Q[remaining, h] (elimination order); with h = 1 they are a Groebner
  // basis of the elimination ideal modulo p, reduced here.
  target.extract = [&](std::vector<ModPoly> basis, const ModularDomain& domain) {
    std::vector<ModPoly> part;
    std::vector<Word> mon(to.stride());
    for (const ModPoly& g : basis) {
      const Word* lead = from.exponents(g.mons.data());
      if (std::any_of(lead, lead + k, [](Word e) { return e != 0; })) continue;
      std::vector<std::pair<std::vector<Word>, std::uint32_t>> terms;
      for (std::size_t t = 0; t < g.size(); ++t) {
        const Word* e = from.exponents(g.mon(t, from.stride()));
        std::copy(e + k, e + k + to.vars(), mon.begin() + static_cast<std::ptrdiff_t>(to.keys()));
        to.encodeKeys(mon.data());
        terms.emplace_back(mon, g.coeffs[t]);
      }
      std::sort(terms.begin(), terms.end(),
                [&](const auto& a, const auto& b) { return to.compare(a.first.data(), b.first.data()) > 0; });
      ModPoly dehomogenized;
      for (auto& [m, c] : terms) dehomogenized.push(m.data(), to.stride(), std::uint32_t{c});
      part.push_back(std::move(dehomogenized));
    }
    Engine<ModularDomain> engine(to, domain, monitor);
    return engine.reduceBasis(std::move(part));
  };
  target.verify = [&](const std::vector<Polynomial>& candidate) {
    Progress progress;
    progress.stage = "verification";
    progress.basisSize = candidate.size();
    for (const Polynomial& f : candidate) {
      // A membership test can take long (a substitution, or a basis of the
      // whole ideal) and need not check the budget itself: none starts once
      // the budget is spent.
      monitor.check(progress);
      if (!contains(f)) return false;
    }
    const FmpzDomain integers;
    Engine<FmpzDomain> engine(to, integers, monitor);
    std::vector<FmpzPoly> packed;
    for (const Polynomial& f : candidate) packed.push_back(toFmpzPoly(toIntegerPoly(f, to)));
    return engine.isGroebner(std::move(packed));
  };
  return modularGroebner(generators, homogeneous, monitor, stats, &target);
}

}  // namespace sdfwb::algebra::gb
