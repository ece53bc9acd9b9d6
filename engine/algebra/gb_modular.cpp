#include "algebra/gb_modular.h"

#include "algebra/gb_convert.h"
#include "algebra/gb_engine.h"
#include "algebra/gb_fglm.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <stdexcept>

namespace sdfwb::algebra::gb {

namespace {

std::uint32_t modP(const mpz_class& value, std::uint32_t p) {
  return static_cast<std::uint32_t>(mpz_fdiv_ui(value.get_mpz_t(), p));
}

// f mod p in the engine's representation; false when p divides a
// denominator or the leading coefficient (such primes are skipped).
bool toModular(const Polynomial& f, const Layout& layout, const ModularDomain& domain, ModPoly& out) {
  const std::size_t stride = layout.stride();
  std::vector<Word> mon(stride);
  out.clear();
  for (const Term& t : f.terms()) {
    std::uint32_t den = modP(t.coefficient.get_den(), domain.p);
    if (den == 0) return false;
    std::uint32_t c;
    domain.mul(c, modP(t.coefficient.get_num(), domain.p), domain.inverse(den));
    if (c == 0) {
      if (&t == &f.terms().front()) return false;
      continue;
    }
    for (std::size_t v = 0; v < layout.vars(); ++v) mon[layout.keys() + v] = static_cast<Word>(t.monomial[v]);
    layout.encodeKeys(mon.data());
    out.push(mon.data(), stride, std::uint32_t{c});
  }
  return true;
}

// The state the lifting stage reports to the budget. The lift can run long
// (its coefficients grow with every prime), so it checks the budget at the
// same kind of safe points as Buchberger; its coefficients are GMP integers,
// which the monitor counts by itself.
Progress lifting(std::size_t polys) {
  Progress progress;
  progress.stage = "lifting";
  progress.basisSize = polys;
  return progress;
}

// Bases modulo the primes that share one set of leading monomials, combined
// by Chinese remaindering: residues modulo the product of those primes.
struct Group {
  std::vector<IntPoly> polys;
  mpz_class modulus = 1;
  std::size_t primes = 0;
  std::size_t nextAttempt = 0;  // reconstruct once primes reaches this
};

// acc (mod M) and next (mod p) -> residues mod M*p over the union of supports.
IntPoly chineseRemainder(const Layout& layout, IntPoly& acc, const mpz_class& modulus, const ModPoly& next,
                          std::uint32_t p, BudgetMonitor& monitor, const Progress& progress) {
  const std::size_t stride = layout.stride();
  const ModularDomain domain{p};
  const std::uint32_t mInverse = domain.inverse(modP(modulus, p));
  if (acc.mons == next.mons) {
    // The usual case, the same support modulo both: combined in place.
    for (std::size_t t = 0; t < acc.size(); ++t) {
      mpz_class& r = acc.coeffs[t];
      const std::uint32_t rMod = modP(r, p);
      const std::uint32_t c = next.coeffs[t];
      std::uint32_t factor;
      domain.mul(factor, c >= rMod ? c - rMod : c + (p - rMod), mInverse);
      mpz_addmul_ui(r.get_mpz_t(), modulus.get_mpz_t(), factor);
      monitor.tick(progress);
    }
    return std::move(acc);
  }
  IntPoly out;
  auto combine = [&](const Word* mon, mpz_class&& r, std::uint32_t c) {
    // r + M * ((c - r) / M mod p)
    std::uint32_t rMod = modP(r, p);
    std::uint32_t diff = c >= rMod ? c - rMod : c + (p - rMod);
    std::uint32_t t;
    domain.mul(t, diff, mInverse);
    mpz_addmul_ui(r.get_mpz_t(), modulus.get_mpz_t(), t);
    out.push(mon, stride, std::move(r));
    monitor.tick(progress);
  };
  std::size_t x = 0, y = 0;
  while (x < acc.size() || y < next.size()) {
    int c = x == acc.size() ? -1 : y == next.size() ? 1 : layout.compare(acc.mon(x, stride), next.mon(y, stride));
    if (c > 0) {
      combine(acc.mon(x, stride), std::move(acc.coeffs[x]), 0);
      ++x;
    } else if (c < 0) {
      combine(next.mon(y, stride), mpz_class(0), next.coeffs[y]);
      ++y;
    } else {
      combine(acc.mon(x, stride), std::move(acc.coeffs[x]), next.coeffs[y]);
      ++x;
      ++y;
    }
  }
  return out;
}

void accumulate(const Layout& layout, Group& group, const std::vector<ModPoly>& basis, std::uint32_t p,
                BudgetMonitor& monitor) {
  if (group.primes == 0) {
    for (const ModPoly& g : basis) {
      IntPoly lifted;
      lifted.mons = g.mons;
      for (std::uint32_t c : g.coeffs) lifted.coeffs.emplace_back(c);
      group.polys.push_back(std::move(lifted));
    }
  } else {
    const Progress progress = lifting(basis.size());
    for (std::size_t i = 0; i < basis.size(); ++i) {
      group.polys[i] = chineseRemainder(layout, group.polys[i], group.modulus, basis[i], p, monitor, progress);
    }
  }
  group.modulus *= p;
  ++group.primes;
}

Monomial toMonomial(const Layout& layout, const Word* mon) {
  Monomial m(layout.vars());
  const Word* e = layout.exponents(mon);
  for (std::size_t v = 0; v < layout.vars(); ++v) m[v] = static_cast<Exponent>(e[v]);
  return m;
}

// Rational reconstruction of every coefficient; nullopt if one fails. The
// coefficient that failed is remembered in `probe` and tried first next
// time, so that while the modulus is still too small a failed attempt costs
// one reconstruction instead of a pass over all coefficients.
std::optional<std::vector<Polynomial>> reconstruct(const Layout& layout, const Group& group, const RingPtr& ring,
                                                   std::pair<std::size_t, std::size_t>& probe, BudgetMonitor& monitor) {
  const std::size_t stride = layout.stride();
  const Progress progress = lifting(group.polys.size());
  const RationalReconstruction reconstruct(group.modulus);
  mpq_class q;
  if (probe.first < group.polys.size() && probe.second < group.polys[probe.first].size() &&
      !reconstruct(group.polys[probe.first].coeffs[probe.second], q)) {
    return std::nullopt;
  }
  std::vector<Polynomial> out;
  for (std::size_t i = 0; i < group.polys.size(); ++i) {
    const IntPoly& g = group.polys[i];
    std::vector<Term> terms;
    terms.reserve(g.size());
    for (std::size_t t = 0; t < g.size(); ++t) {
      if (mpz_sgn(g.coeffs[t].get_mpz_t()) == 0) continue;
      monitor.tick(progress);
      if (!reconstruct(g.coeffs[t], q)) {
        probe = {i, t};
        return std::nullopt;
      }
      terms.push_back(Term{toMonomial(layout, g.mon(t, stride)), std::move(q)});
    }
    out.emplace_back(ring, std::move(terms));
  }
  return out;
}

// The candidate reduced mod p equals the basis computed mod p.
bool agreesModulo(const Layout& layout, const std::vector<Polynomial>& candidate, const std::vector<ModPoly>& basis,
                   std::uint32_t p, BudgetMonitor& monitor) {
  if (candidate.size() != basis.size()) return false;
  const ModularDomain domain{p};
  const Progress progress = lifting(basis.size());
  ModPoly reduced;
  for (std::size_t i = 0; i < basis.size(); ++i) {
    // Once per polynomial, as Buchberger's interreduction does: reducing a
    // polynomial with rational coefficients costs far more than the check.
    monitor.check(progress);
    if (!toModular(candidate[i], layout, domain, reduced)) return false;
    if (reduced.mons != basis[i].mons || reduced.coeffs != basis[i].coeffs) return false;
  }
  return true;
}

// Exact check over Q: the candidate is a Groebner basis and contains the input.
bool verify(const Layout& layout, const std::vector<Polynomial>& candidate, const std::vector<Polynomial>& input,
            BudgetMonitor& monitor, GroebnerStats& stats) {
  const FmpzDomain domain;
  std::vector<FmpzPoly> packed;
  for (const Polynomial& g : candidate) packed.push_back(toFmpzPoly(toIntegerPoly(g, layout)));
  Engine<FmpzDomain> membership(layout, domain, monitor);
  membership.setBasis(packed);
  for (const Polynomial& f : input) {
    if (f.isZero()) continue;
    if (!membership.normalForm(toFmpzPoly(toIntegerPoly(f, layout))).empty()) return false;
  }
  Engine<FmpzDomain> pairs(layout, domain, monitor);
  bool ok = pairs.isGroebner(std::move(packed));
  stats.verificationPairs += pairs.stats().pairsTreated;
  return ok;
}

}  // namespace

std::uint32_t previousPrime(std::uint32_t below) {
  auto mulMod = [](std::uint64_t a, std::uint64_t b, std::uint64_t m) { return a * b % m; };
  auto powMod = [&](std::uint64_t b, std::uint64_t e, std::uint64_t m) {
    std::uint64_t r = 1;
    for (b %= m; e; e >>= 1, b = mulMod(b, b, m)) {
      if (e & 1) r = mulMod(r, b, m);
    }
    return r;
  };
  auto isPrime = [&](std::uint32_t n) {
    if (n < 2) return false;
    for (std::uint32_t small : {2u, 3u, 5u, 7u, 11u, 13u}) {
      if (n % small == 0) return n == small;
    }
    std::uint32_t d = n - 1;
    int s = 0;
    while ((d & 1) == 0) {
      d >>= 1;
      ++s;
    }
    // Bases 2, 7, 61 decide primality for every n < 2^32.
    for (std::uint64_t a : {2u, 7u, 61u}) {
      std::uint64_t x = powMod(a, d, n);
      if (x == 1 || x == n - 1) continue;
      bool composite = true;
      for (int r = 1; r < s && composite; ++r) {
        x = mulMod(x, x, n);
        if (x == n - 1) composite = false;
      }
      if (composite) return false;
    }
    return true;
  };
  for (std::uint32_t n = below - 1; n > 1; --n) {
    if (isPrime(n)) return n;
  }
  throw std::logic_error("previous_prime: no prime below " + std::to_string(below));
}

RationalReconstruction::RationalReconstruction(const mpz_class& modulus) {
  fmpz_init(modulus_);
  fmpz_init(residue_);
  fmpq_init(value_);
  fmpz_set_mpz(modulus_, modulus.get_mpz_t());
}

RationalReconstruction::~RationalReconstruction() {
  fmpq_clear(value_);
  fmpz_clear(residue_);
  fmpz_clear(modulus_);
}

bool RationalReconstruction::operator()(const mpz_class& a, mpq_class& out) const {
  // FLINT's fmpq_reconstruct_fmpz (half-gcd for large moduli) with the
  // balanced bounds |n|, d <= sqrt(m/2): the lift spent a fifth of Katsura-6
  // in a plain Euclid over mpz_class temporaries.
  fmpz_set_mpz(residue_, a.get_mpz_t());
  fmpz_mod(residue_, residue_, modulus_);
  if (!fmpq_reconstruct_fmpz(value_, residue_, modulus_)) return false;
  fmpz_get_mpz(out.get_num_mpz_t(), fmpq_numref(value_));
  fmpz_get_mpz(out.get_den_mpz_t(), fmpq_denref(value_));
  return true;
}

namespace {

// Collects bases modulo successive primes and proposes candidates over Q.
class Lifter {
 public:
  Lifter(const Layout& layout, RingPtr ring, BudgetMonitor& monitor)
      : layout_(layout), ring_(std::move(ring)), monitor_(monitor) {}

  /// The current candidate, if it reduces modulo p to `basis`.
  const std::vector<Polynomial>* agreeing(const std::vector<ModPoly>& basis, std::uint32_t p) const {
    if (!candidate_ || candidateGroup_ != groupOf(basis)) return nullptr;
    return agreesModulo(layout_, *candidate_, basis, p, monitor_) ? &*candidate_ : nullptr;
  }

  /// Adds a basis modulo p to its group (primes with the same leading
  /// monomials); the largest group proposes the candidate.
  void add(const std::vector<ModPoly>& basis, std::uint32_t p) {
    std::size_t index = groupOf(basis);
    if (index == groups_.size()) {
      groups_.emplace_back();
      leads_.push_back(leads(basis));
    }
    accumulate(layout_, groups_[index], basis, p, monitor_);
    std::size_t largest = 0;
    for (std::size_t g = 1; g < groups_.size(); ++g) {
      if (groups_[g].primes > groups_[largest].primes) largest = g;
    }
    if (largest == index) {
      // Reconstruction costs about as much as a pass of Euclid over every
      // coefficient, so it is attempted on a geometric schedule (at most 1/8
      // more primes than strictly needed) rather than after every prime.
      Group& group = groups_[index];
      if (group.primes >= group.nextAttempt) {
        candidate_ = reconstruct(layout_, group, ring_, probe_, monitor_);
        candidateGroup_ = index;
        group.nextAttempt = group.primes + 1 + group.primes / 8;
      }
    } else if (candidateGroup_ != largest) {
      candidate_.reset();
    }
  }

 private:
  std::vector<Word> leads(const std::vector<ModPoly>& basis) const {
    std::vector<Word> out;
    for (const ModPoly& g : basis) out.insert(out.end(), g.mons.begin(), g.mons.begin() + layout_.stride());
    return out;
  }
  std::size_t groupOf(const std::vector<ModPoly>& basis) const {
    std::vector<Word> l = leads(basis);
    std::size_t index = 0;
    while (index < leads_.size() && leads_[index] != l) ++index;
    return index;
  }

  const Layout& layout_;
  RingPtr ring_;
  BudgetMonitor& monitor_;
  std::vector<Group> groups_;
  std::vector<std::vector<Word>> leads_;  // leading monomials of each group
  std::optional<std::vector<Polynomial>> candidate_;
  std::size_t candidateGroup_ = 0;
  std::pair<std::size_t, std::size_t> probe_{0, 0};  // see reconstruct
};

constexpr std::size_t kMaxPrimes = 100000;

}  // namespace

std::vector<Polynomial> modularGroebner(const std::vector<Polynomial>& input, const RingPtr& ring,
                                         BudgetMonitor& monitor, GroebnerStats& stats, const LiftTarget* target,
                                         const RecordedRun* recorded) {
  const Layout layout(*ring);
  const Layout targetLayout(target ? *target->ring : *ring);
  Lifter lifter(targetLayout, target ? target->ring : ring, monitor);
  // The first prime runs Buchberger in full and records its useful steps;
  // later primes replay them, skipping the pairs that reduce to zero. A
  // replay that does not fit runs in full and records a new trace. A run
  // recorded by the caller is replayed from the first prime on.
  std::optional<Trace> trace;
  // The counters of the last full modular run, with the method's own.
  auto fullRunStats = [&stats](const GroebnerStats& run) {
    const std::size_t primes = stats.primes, replays = stats.replays;
    stats = run;
    stats.primes = primes;
    stats.replays = replays;
  };
  if (recorded) {
    trace = recorded->trace;
    fullRunStats(recorded->stats);
  }
  std::uint32_t p = 0x80000000u;
  for (std::size_t attempt = 0; attempt < kMaxPrimes; ++attempt) {
    p = previousPrime(p);
    const ModularDomain domain{p};
    std::vector<ModPoly> reduced(input.size());
    bool usable = true;
    for (std::size_t i = 0; i < input.size() && usable; ++i) usable = toModular(input[i], layout, domain, reduced[i]);
    if (!usable) continue;
    std::optional<std::vector<ModPoly>> replayed;
    if (trace) {
      Engine<ModularDomain> engine(layout, domain, monitor);
      replayed = engine.replay(reduced, *trace, !target);
      if (replayed) ++stats.replays;
    }
    std::vector<ModPoly> basis;
    if (replayed) {
      basis = std::move(*replayed);
    } else {
      Engine<ModularDomain> engine(layout, domain, monitor);
      trace.emplace();
      basis = engine.groebner(std::move(reduced), &*trace, !target);
      fullRunStats(engine.stats());
    }
    ++stats.primes;
    monitor.setPrimes(stats.primes);
    if (target) basis = target->extract(std::move(basis), domain);
    if (const std::vector<Polynomial>* candidate = lifter.agreeing(basis, p)) {
      const bool verified =
          target ? target->verify(*candidate) : verify(layout, *candidate, input, monitor, stats);
      if (verified) return *candidate;
    }
    lifter.add(basis, p);
  }
  throw std::logic_error("modular Groebner basis: no verified result after many primes");
}

bool zeroDimensionalModuloAPrime(const std::vector<Polynomial>& input, const RingPtr& ring,
                                     BudgetMonitor& monitor, RecordedRun* run) {
  const Layout layout(*ring);
  for (std::uint32_t p = previousPrime(0x80000000u);; p = previousPrime(p)) {
    const ModularDomain domain{p};
    std::vector<ModPoly> reduced(input.size());
    bool usable = true;
    for (std::size_t i = 0; i < input.size() && usable; ++i) usable = toModular(input[i], layout, domain, reduced[i]);
    if (!usable) continue;
    Engine<ModularDomain> engine(layout, domain, monitor);
    Trace trace;
    std::vector<ModPoly> basis = engine.groebner(std::move(reduced), &trace);
    std::vector<const Word*> leads;
    for (const ModPoly& g : basis) leads.push_back(g.mons.data());
    const bool zeroDimensional = !basis.empty() && staircaseSize(layout, leads).has_value();
    if (run) *run = RecordedRun{std::move(trace), engine.stats()};
    return zeroDimensional;
  }
}

std::optional<std::vector<Polynomial>> modularFglm(const std::vector<Polynomial>& basis, const RingPtr& target,
                                                    BudgetMonitor& monitor, GroebnerStats& stats) {
  if (basis.empty()) return std::nullopt;  // the zero ideal is not zero-dimensional
  const RingPtr& sourceRing = basis.front().ring();
  const Layout source(*sourceRing);
  const Layout layout(*target);
  std::vector<IntPoly> packed;
  std::vector<const Word*> leads;
  for (const Polynomial& g : basis) packed.push_back(toIntegerPoly(g, source));
  for (const IntPoly& g : packed) leads.push_back(g.mons.data());
  const std::optional<std::size_t> dimension = staircaseSize(source, leads);
  if (!dimension) return std::nullopt;
  const std::optional<MultiplicationTable> table = multiplicationTable(source, packed, monitor);

  // Exact check of a candidate L: every element reduces to 0 by the basis
  // (so <L> is inside the ideal) and L's staircase has the quotient's
  // dimension. Then dim Q[x]/<L> <= |staircase(L)| = dim Q[x]/I <= dim
  // Q[x]/<L>, so <L> = I and L is a Groebner basis of it.
  auto verified = [&](const std::vector<Polynomial>& candidate) {
    std::vector<IntPoly> targetPacked;
    std::vector<const Word*> targetLeads;
    for (const Polynomial& l : candidate) targetPacked.push_back(toIntegerPoly(l, layout));
    for (const IntPoly& l : targetPacked) targetLeads.push_back(l.mons.data());
    if (staircaseSize(layout, targetLeads) != dimension) return false;
    return allInIdeal(*table, layout, targetPacked, monitor);
  };

  Lifter lifter(layout, target, monitor);
  std::uint32_t p = 0x80000000u;
  for (std::size_t attempt = 0; attempt < kMaxPrimes; ++attempt) {
    p = previousPrime(p);
    const ModularDomain domain{p};
    std::optional<std::vector<ModPoly>> modular = fglmModulo(*table, layout, domain, monitor);
    if (!modular) continue;
    const std::vector<ModPoly>& converted = *modular;
    ++stats.primes;
    monitor.setPrimes(stats.primes);
    if (const std::vector<Polynomial>* candidate = lifter.agreeing(converted, p)) {
      if (verified(*candidate)) return *candidate;
    }
    lifter.add(converted, p);
  }
  throw std::logic_error("modular FGLM: no verified result after many primes");
}

}  // namespace sdfwb::algebra::gb
