// The modular method's runs modulo later primes: a replayed trace gives the
// basis a fresh run gives, a trace that does not fit a prime is refused,
// and a first prime handed in from outside (the zero-dimensionality test's
// run, PrimeRun) gives the fresh result, and is outvoted when it is wrong.

#include "algebra/gb_engine.h"
#include "algebra/gb_modular.h"
#include "algebra/groebner.h"
#include "example_systems.h"

#include <gtest/gtest.h>

namespace sdfwb::algebra::gb {
namespace {

std::vector<ModPoly> modular(const Ideal& ideal, const Layout& layout, const ModularDomain& domain) {
  std::vector<ModPoly> out;
  for (const Polynomial& f : ideal.generators()) {
    ModPoly g;
    for (const Term& t : f.terms()) {
      std::vector<Word> mon(layout.stride());
      for (std::size_t v = 0; v < layout.vars(); ++v) mon[layout.keys() + v] = static_cast<Word>(t.monomial[v]);
      layout.encodeKeys(mon.data());
      const auto num = static_cast<std::uint32_t>(mpz_fdiv_ui(t.coefficient.get_num_mpz_t(), domain.p));
      const auto den = static_cast<std::uint32_t>(mpz_fdiv_ui(t.coefficient.get_den_mpz_t(), domain.p));
      std::uint32_t c;
      domain.mul(c, num, domain.inverse(den));
      if (c != 0) g.push(mon.data(), layout.stride(), std::uint32_t{c});
    }
    out.push_back(std::move(g));
  }
  return out;
}

struct TracedRun {
  std::vector<ModPoly> basis;
  Trace trace;
};

TracedRun fresh(const Ideal& ideal, const Layout& layout, std::uint32_t p) {
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  const ModularDomain domain{p};
  Engine<ModularDomain> engine(layout, domain, monitor);
  TracedRun run;
  run.basis = engine.groebner(modular(ideal, layout, domain), &run.trace);
  return run;
}

std::optional<std::vector<ModPoly>> replayed(const Ideal& ideal, const Layout& layout, std::uint32_t p,
                                             const Trace& trace) {
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  const ModularDomain domain{p};
  Engine<ModularDomain> engine(layout, domain, monitor);
  return engine.replay(modular(ideal, layout, domain), trace);
}

void expectSameBasis(const std::vector<ModPoly>& a, const std::vector<ModPoly>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].mons, b[i].mons) << "element " << i;
    EXPECT_EQ(a[i].coeffs, b[i].coeffs) << "element " << i;
  }
}

const std::uint32_t kFirst = previousPrime(0x80000000u);
const std::uint32_t kSecond = previousPrime(kFirst);

TEST(ModularTrace, ReplayModuloAnotherPrimeEqualsAFreshRun) {
  for (const Ideal& ideal : {testing::katsura(4), testing::cyclic(5)}) {
    const Layout layout(*ideal.ring());
    const TracedRun first = fresh(ideal, layout, kFirst);
    const TracedRun second = fresh(ideal, layout, kSecond);
    std::optional<std::vector<ModPoly>> replay = replayed(ideal, layout, kSecond, first.trace);
    ASSERT_TRUE(replay.has_value());
    expectSameBasis(*replay, second.basis);
    // The replay reduces only the useful pairs: one step per new element.
    EXPECT_LT(first.trace.steps.size(), 3 * second.basis.size() + ideal.generators().size());
  }
}

TEST(ModularTrace, ATraceOfAnotherIdealIsRefused) {
  // Katsura-4's trace does not fit Katsura-4 with one generator changed:
  // some step gives another leading monomial (or a step refers to an
  // element the replay does not have), and the replay says so instead of
  // returning a basis.
  const Ideal ideal = testing::katsura(4);
  std::vector<Polynomial> changed = ideal.generators();
  changed.back() += pow(ideal.ring()->var(ideal.ring()->size() - 1), 2);
  const Ideal other(ideal.ring(), changed);
  const Layout layout(*ideal.ring());
  const TracedRun first = fresh(ideal, layout, kFirst);
  EXPECT_FALSE(replayed(other, layout, kSecond, first.trace).has_value());
}

TEST(ModularTrace, ARecordedRunIsReplayedFromTheFirstPrime) {
  // The zero-dimensionality test's run, handed to the modular method: every
  // prime replays it (none runs in full), and the basis is the fresh one.
  const Ideal ideal = testing::katsura(4);
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  RecordedRun run;
  ASSERT_TRUE(zeroDimensionalModuloAPrime(ideal.generators(), ideal.ring(), monitor, &run));
  GroebnerStats seededStats, freshStats;
  const std::vector<Polynomial> seeded =
      modularGroebner(ideal.generators(), ideal.ring(), monitor, seededStats, nullptr, &run);
  const std::vector<Polynomial> fromScratch = modularGroebner(ideal.generators(), ideal.ring(), monitor, freshStats);
  EXPECT_EQ(seeded, fromScratch);
  EXPECT_EQ(seededStats.primes, freshStats.primes);
  EXPECT_EQ(seededStats.replays, seededStats.primes);
  EXPECT_EQ(freshStats.replays, freshStats.primes - 1);
  EXPECT_EQ(seededStats.pairsTreated, freshStats.pairsTreated);  // the recorded run's counters
}

TEST(ModularTrace, ARecordedRunOfAnotherIdealRunsInFull) {
  // A wrong recorded run (that of Katsura-4 with one generator changed)
  // does not replay: the first prime runs in full and records its own
  // trace, and the result is the basis over Q.
  const Ideal ideal = testing::katsura(4);
  std::vector<Polynomial> changed = ideal.generators();
  changed.back() += pow(ideal.ring()->var(ideal.ring()->size() - 1), 2);
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  RecordedRun wrong;
  ASSERT_TRUE(zeroDimensionalModuloAPrime(changed, ideal.ring(), monitor, &wrong));
  GroebnerStats stats;
  const std::vector<Polynomial> basis =
      modularGroebner(ideal.generators(), ideal.ring(), monitor, stats, nullptr, &wrong);
  GroebnerOptions overQ;
  overQ.method = GroebnerMethod::Rational;
  EXPECT_EQ(basis, groebnerBasis(ideal, overQ).basis);
  EXPECT_EQ(stats.replays, stats.primes - 1);
}

TEST(ModularTrace, ABadPrimeIsOutvoted) {
  // The first prime's basis made bad on purpose (its last element dropped:
  // other leading monomials, as an unlucky prime has): the lift groups it
  // apart, the next primes outvote it, and the verified result is right.
  const Ideal ideal = testing::katsura(3);
  GroebnerOptions overQ;
  overQ.method = GroebnerMethod::Rational;
  const std::vector<Polynomial> expected = groebnerBasis(ideal, overQ).basis;
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  std::size_t bases = 0, verified = 0;
  LiftTarget target;
  target.ring = ideal.ring();
  const Layout layout(*ideal.ring());
  target.extract = [&](std::vector<ModPoly> basis, const ModularDomain& domain) {
    // With a target the primes' bases come minimal, not reduced.
    Engine<ModularDomain> engine(layout, domain, monitor);
    basis = engine.reduceBasis(std::move(basis));
    if (++bases == 1) basis.pop_back();
    return basis;
  };
  target.verify = [&](const std::vector<Polynomial>& candidate) {
    ++verified;
    return candidate == expected;
  };
  GroebnerStats stats;
  EXPECT_EQ(modularGroebner(ideal.generators(), ideal.ring(), monitor, stats, &target), expected);
  EXPECT_GE(bases, 3u);  // the bad prime, and two to outvote and confirm
  EXPECT_EQ(verified, 1u);  // the bad group's candidate never reached the check
}

}  // namespace
}  // namespace sdfwb::algebra::gb
