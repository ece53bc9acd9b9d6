#include "algebra/gb_engine.h"

#include <algorithm>

namespace sdfwb::algebra::gb {

template <class D>
Engine<D>::Engine(const Layout& layout, const D& domain, BudgetMonitor& monitor)
    : layout_(layout),
      domain_(domain),
      monitor_(monitor),
      bucket_(layout, domain),
      leadTerm_(layout.stride()),
      shift_(layout.stride()) {}

template <class D>
Progress Engine<D>::progress(const char* stage) const {
  Progress p;
  p.basisSize = reducers_.size();
  p.pairsLeft = livePairs_;
  p.stage = stage;
  return p;
}

template <class D>
std::size_t Engine<D>::ownBytes() const {
  return basisBytes_ + bucket_.bytes() + pairs_.capacity() * sizeof(Pair) +
         lcmStore_.capacity() * sizeof(Word);
}

template <class D>
int Engine<D>::findReducer(const Word* mon, std::uint64_t mask) const {
  for (std::uint32_t r : reducers_) {
    if ((basis_[r].mask & ~mask) != 0) continue;
    if (layout_.divides(lead(r), mon)) return static_cast<int>(r);
  }
  return -1;
}

template <class D>
typename Engine<D>::P Engine<D>::reduce(P result, std::uint32_t sugar, Coeff* scaleProduct) {
  const std::size_t stride = layout_.stride();
  Word* mon = leadTerm_.data();
  Word* shift = shift_.data();
  Coeff c{}, scale{}, multiplier{};
  // Bits multiplied into the polynomial since the last content removal.
  std::size_t scaledBits = 0;
  while (bucket_.popLead(mon, c)) {
    int r = findReducer(mon, layout_.divmask(mon));
    if (r < 0) {
      result.push(mon, stride, std::move(c));
      continue;
    }
    const P& g = basis_[r].poly;
    domain_.cancelFactors(c, g.coeffs.front(), scale, multiplier);
    if (!D::isOne(scale)) {
      bucket_.scale(scale);
      for (Coeff& x : result.coeffs) domain_.mul(x, x, scale);
      if (scaleProduct) domain_.mul(*scaleProduct, *scaleProduct, scale);
      if constexpr (D::hasContent) scaledBits += D::bits(scale);
    }
    domain_.negate(multiplier);
    layout_.divide(shift, mon, g.mons.data());
    if (g.size() > 1) bucket_.addMultiple(g, 1, multiplier, shift);
    monitor_.addWork(g.size());
    sugar = std::max(sugar, layout_.sugarDegree(shift) + g.sugar);
    if constexpr (D::hasContent) {
      if (scaledBits > kContentBits && !scaleProduct) {
        removeContent(result);
        scaledBits = 0;
      }
    }
    ++stats_.reductionSteps;
    monitor_.tick(progress("reduction"), ownBytes());
  }
  result.sugar = sugar;
  if (!scaleProduct) domain_.normalize(result.coeffs);
  return result;
}

template <class D>
void Engine<D>::removeContent(P& result) {
  if constexpr (D::hasContent) {
    // gcd of all coefficients, stopping as soon as it reaches 1 (cheap when
    // there is nothing to gain).
    Coeff g{};
    auto accumulate = [&g](const Coeff& c) { return D::gcdAboveOne(g, c); };
    for (const Coeff& c : result.coeffs) {
      if (!accumulate(c)) return;
    }
    bucket_.forEachCoefficient(accumulate);
    if (D::isZero(g) || D::isOne(g)) return;
    auto divide = [&g](Coeff& c) {
      D::divideExact(c, g);
      return true;
    };
    for (Coeff& c : result.coeffs) divide(c);
    bucket_.forEachCoefficient(divide);
    ++stats_.contentRemovals;
  }
}

template <class D>
bool Engine<D>::pairBefore(std::uint32_t a, std::uint32_t b) const {
  const Pair& pa = pairs_[a];
  const Pair& pb = pairs_[b];
  if (pa.sugar != pb.sugar) return pa.sugar < pb.sugar;
  int c = layout_.compare(pairLcm(pa), pairLcm(pb));
  if (c != 0) return c < 0;
  return a < b;
}

template <class D>
std::optional<typename Engine<D>::Pair> Engine<D>::nextPair(const char* stage) {
  const auto later = [this](std::uint32_t a, std::uint32_t b) { return pairBefore(b, a); };
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    Pair pair = pairs_[heap_.back()];
    heap_.pop_back();
    if (!pair.alive) continue;
    --livePairs_;
    monitor_.check(progress(stage), ownBytes());
    ++stats_.pairsTreated;
    return pair;
  }
  return std::nullopt;
}

template <class D>
void Engine<D>::pushPair(std::uint32_t i, std::uint32_t j, std::uint32_t sugar, const Word* lcm) {
  Pair pair{i, j, sugar, lcmStore_.size(), layout_.divmask(lcm)};
  lcmStore_.insert(lcmStore_.end(), lcm, lcm + layout_.stride());
  pairs_.push_back(pair);
  heap_.push_back(static_cast<std::uint32_t>(pairs_.size() - 1));
  std::push_heap(heap_.begin(), heap_.end(), [this](std::uint32_t a, std::uint32_t b) { return pairBefore(b, a); });
  ++livePairs_;
}

template <class D>
void Engine<D>::insert(P h) {
  const std::size_t stride = layout_.stride();
  const auto k = static_cast<std::uint32_t>(basis_.size());
  // The criteria look at every element once per insertion.
  monitor_.addWork(k);
  basisBytes_ += h.bytes();
  Element element{std::move(h), 0};
  element.mask = layout_.divmask(element.poly.mons.data());
  basis_.push_back(std::move(element));
  const Word* leadK = lead(k);
  const std::uint32_t sugarK = basis_[k].poly.sugar;
  const std::uint32_t degreeK = layout_.sugarDegree(leadK);

  // New pairs (i, k) with the current non-redundant elements, filtered by
  // Gebauer-Moeller's criteria M, F and the product criterion B_k.
  // The criteria compare exponents only: the lcms' order keys (a matrix
  // product each) are encoded for the pairs kept, and divisibility masks
  // reject most candidate divisors before the exponents are read.
  const std::size_t m = reducers_.size();
  std::vector<Word> lcms(m * stride);
  std::vector<std::uint64_t> masks(m);
  std::vector<char> coprime(m), keep(m, 1);
  for (std::size_t a = 0; a < m; ++a) {
    layout_.lcmExponents(lcms.data() + a * stride, lead(reducers_[a]), leadK);
    masks[a] = layout_.divmask(lcms.data() + a * stride);
    coprime[a] = layout_.coprime(lead(reducers_[a]), leadK);
  }
  for (std::size_t a = 0; a < m; ++a) {  // M: an lcm properly divisible by another's
    for (std::size_t b = 0; b < m; ++b) {
      if (b == a || (masks[b] & ~masks[a]) != 0 ||
          !layout_.divides(lcms.data() + b * stride, lcms.data() + a * stride)) {
        continue;
      }
      if (!layout_.equal(lcms.data() + b * stride, lcms.data() + a * stride)) {
        keep[a] = 0;
        ++stats_.chainCriterion;
        break;
      }
    }
  }
  for (std::size_t a = 0; a < m; ++a) {  // F: one pair per lcm; none if one of them is coprime
    if (!keep[a]) continue;
    for (std::size_t b = a + 1; b < m; ++b) {
      if (keep[b] && masks[a] == masks[b] && layout_.equal(lcms.data() + a * stride, lcms.data() + b * stride)) {
        coprime[a] = coprime[a] || coprime[b];
        keep[b] = 0;
        ++stats_.chainCriterion;
      }
    }
    if (coprime[a]) {
      keep[a] = 0;
      ++stats_.productCriterion;
    }
  }

  // Old pairs (i, j) whose lcm is divisible by lt(k) and differs from both
  // lcm(i, k) and lcm(j, k): the chain i - k - j makes them useless.
  auto lcmEquals = [&](const Word* x, const Word* y, const Word* l) {
    for (std::size_t v = layout_.keys(); v < stride; ++v) {
      if (std::max(x[v], y[v]) != l[v]) return false;
    }
    return true;
  };
  const std::uint64_t maskK = basis_[k].mask;
  for (std::uint32_t index : heap_) {
    Pair& pair = pairs_[index];
    if (!pair.alive || pair.j == kGenerator || (maskK & ~pair.mask) != 0) continue;
    const Word* l = pairLcm(pair);
    if (!layout_.divides(leadK, l)) continue;
    if (lcmEquals(lead(pair.i), leadK, l) || lcmEquals(lead(pair.j), leadK, l)) continue;
    pair.alive = false;
    --livePairs_;
    ++stats_.chainCriterion;
  }

  for (std::size_t a = 0; a < m; ++a) {
    if (!keep[a]) continue;
    const std::uint32_t i = reducers_[a];
    layout_.encodeKeys(lcms.data() + a * stride);
    const std::uint32_t sugarI = basis_[i].poly.sugar;
    const std::uint32_t degreeI = layout_.sugarDegree(lead(i));
    const std::uint32_t degreeL = layout_.sugarDegree(lcms.data() + a * stride);
    // Sugar bounds the degree, so sugar >= degree of the leading monomial;
    // signed arithmetic keeps a violation from wrapping around.
    const std::int64_t ecart = std::max<std::int64_t>(std::int64_t{sugarI} - degreeI, std::int64_t{sugarK} - degreeK);
    const auto sugar = static_cast<std::uint32_t>(std::max<std::int64_t>(0, ecart) + degreeL);
    pushPair(i, k, sugar, lcms.data() + a * stride);
  }

  // Elements whose leading monomial lt(k) divides are no longer needed,
  // neither for new pairs nor as reducers.
  std::vector<std::uint32_t> kept;
  for (std::uint32_t r : reducers_) {
    if (layout_.divides(leadK, lead(r))) {
      basis_[r].redundant = true;
    } else {
      kept.push_back(r);
    }
  }
  kept.push_back(k);
  reducers_ = std::move(kept);
  stats_.maxBasisSize = std::max(stats_.maxBasisSize, reducers_.size());
}

template <class D>
void Engine<D>::interreduce() {
  const std::size_t stride = layout_.stride();
  for (std::uint32_t r : reducers_) {
    const P& g = basis_[r].poly;
    P result;
    result.push(g.mons.data(), stride, Coeff(g.coeffs.front()));
    P tail;
    tail.mons.assign(g.mons.begin() + static_cast<std::ptrdiff_t>(stride), g.mons.end());
    tail.coeffs.assign(g.coeffs.begin() + 1, g.coeffs.end());
    bucket_.clear();
    bucket_.add(std::move(tail));
    P reduced = reduce(std::move(result), g.sugar);
    monitor_.check(progress("interreduction"), ownBytes());
    basis_[r].poly = std::move(reduced);
  }
}

template <class D>
void Engine<D>::loadSPolynomial(std::uint32_t i, std::uint32_t j, const Word* lcm) {
  const std::size_t stride = layout_.stride();
  const P& f = basis_[i].poly;
  const P& g = basis_[j].poly;
  monitor_.addWork(f.size() + g.size());
  Coeff scale{}, multiplier{};
  domain_.cancelFactors(f.coeffs.front(), g.coeffs.front(), scale, multiplier);
  domain_.negate(multiplier);
  std::vector<Word> shift(stride);
  bucket_.clear();
  if (f.size() > 1) {
    layout_.divide(shift.data(), lcm, f.mons.data());
    bucket_.addMultiple(f, 1, scale, shift.data());
  }
  if (g.size() > 1) {
    layout_.divide(shift.data(), lcm, g.mons.data());
    bucket_.addMultiple(g, 1, multiplier, shift.data());
  }
}

template <class D>
void Engine<D>::loadGenerators(std::vector<P>& input) {
  const std::size_t stride = layout_.stride();
  for (P& f : input) {
    if (f.empty()) continue;
    domain_.normalize(f.coeffs);
    std::uint32_t degree = 0;
    for (std::size_t t = 0; t < f.size(); ++t) degree = std::max(degree, layout_.sugarDegree(f.mon(t, stride)));
    f.sugar = degree;
    generators_.push_back(std::move(f));
  }
}

template <class D>
std::vector<typename Engine<D>::P> Engine<D>::finish(bool reduceTails) {
  if (reduceTails) interreduce();
  std::vector<P> result;
  for (std::uint32_t r : reducers_) result.push_back(std::move(basis_[r].poly));
  std::sort(result.begin(), result.end(), [&](const P& a, const P& b) {
    return layout_.compare(a.mons.data(), b.mons.data()) < 0;
  });
  return result;
}

template <class D>
std::vector<typename Engine<D>::P> Engine<D>::groebner(std::vector<P> input, Trace* record, bool reduceTails) {
  loadGenerators(input);
  for (std::uint32_t g = 0; g < generators_.size(); ++g) {
    pushPair(g, kGenerator, generators_[g].sugar, generators_[g].mons.data());
  }
  while (std::optional<Pair> next = nextPair("buchberger")) {
    const Pair& pair = *next;
    bucket_.clear();
    if (pair.j == kGenerator) {
      P copy = generators_[pair.i];
      bucket_.add(std::move(copy));
    } else {
      loadSPolynomial(pair.i, pair.j, pairLcm(pair));
    }
    P h = reduce(P{}, pair.sugar);
    if (h.empty()) {
      ++stats_.zeroReductions;
      continue;
    }
    if (record) record->steps.push_back({pair.i, pair.j, std::vector<Word>(h.mons.begin(), h.mons.begin() + layout_.stride())});
    if (layout_.degree(h.mons.data()) == 0) {
      // A nonzero constant: the ideal is the whole ring.
      for (std::uint32_t r : reducers_) basis_[r].redundant = true;
      reducers_.clear();
      heap_.clear();
      livePairs_ = 0;
      insert(std::move(h));
      break;
    }
    insert(std::move(h));
  }
  return finish(reduceTails);
}

template <class D>
std::optional<std::vector<typename Engine<D>::P>> Engine<D>::replay(std::vector<P> input, const Trace& trace,
                                                                    bool reduceTails) {
  const std::size_t stride = layout_.stride();
  loadGenerators(input);
  std::vector<Word> lcm(stride);
  for (const Trace::Step& step : trace.steps) {
    monitor_.check(progress("replay"), ownBytes());
    ++stats_.pairsTreated;
    std::uint32_t sugar;
    if (step.j == kGenerator) {
      if (step.i >= generators_.size()) return std::nullopt;
      bucket_.clear();
      P copy = generators_[step.i];
      sugar = copy.sugar;
      bucket_.add(std::move(copy));
    } else {
      if (step.i >= basis_.size() || step.j >= basis_.size()) return std::nullopt;
      layout_.lcm(lcm.data(), lead(step.i), lead(step.j));
      loadSPolynomial(step.i, step.j, lcm.data());
      sugar = std::max(basis_[step.i].poly.sugar, basis_[step.j].poly.sugar) + layout_.sugarDegree(lcm.data());
    }
    P h = reduce(P{}, sugar);
    if (h.empty() || !std::equal(step.lead.begin(), step.lead.end(), h.mons.begin())) return std::nullopt;
    // Like insert, without pairs: only the reducers need maintaining.
    const auto k = static_cast<std::uint32_t>(basis_.size());
    basisBytes_ += h.bytes();
    Element element{std::move(h), 0};
    element.mask = layout_.divmask(element.poly.mons.data());
    basis_.push_back(std::move(element));
    std::vector<std::uint32_t> kept;
    for (std::uint32_t r : reducers_) {
      if (layout_.divides(lead(k), lead(r))) {
        basis_[r].redundant = true;
      } else {
        kept.push_back(r);
      }
    }
    kept.push_back(k);
    reducers_ = std::move(kept);
  }
  return finish(reduceTails);
}

template <class D>
bool Engine<D>::isGroebner(std::vector<P> basis) {
  const std::size_t stride = layout_.stride();
  for (P& g : basis) {
    if (g.empty()) continue;
    std::uint32_t degree = 0;
    for (std::size_t t = 0; t < g.size(); ++t) degree = std::max(degree, layout_.sugarDegree(g.mon(t, stride)));
    g.sugar = degree;
    insert(std::move(g));
  }
  while (std::optional<Pair> pair = nextPair("verification")) {
    loadSPolynomial(pair->i, pair->j, pairLcm(*pair));
    if (!reduce(P{}, pair->sugar).empty()) return false;
    ++stats_.zeroReductions;
  }
  return true;
}

template <class D>
std::vector<typename Engine<D>::P> Engine<D>::reduceBasis(std::vector<P> basis) {
  setBasis(std::move(basis));
  std::vector<std::uint32_t> minimal;
  for (std::uint32_t i : reducers_) {
    bool redundant = false;
    for (std::uint32_t j : reducers_) {
      if (j == i || !layout_.divides(lead(j), lead(i))) continue;
      // Of equal leading monomials keep the first.
      if (!layout_.equal(lead(j), lead(i)) || j < i) redundant = true;
    }
    if (!redundant) minimal.push_back(i);
  }
  reducers_ = std::move(minimal);
  return finish();
}

template <class D>
void Engine<D>::setBasis(std::vector<P> basis) {
  basis_.clear();
  reducers_.clear();
  for (P& g : basis) {
    if (g.empty()) continue;
    Element element{std::move(g), 0};
    element.mask = layout_.divmask(element.poly.mons.data());
    basisBytes_ += element.poly.bytes();
    basis_.push_back(std::move(element));
    reducers_.push_back(static_cast<std::uint32_t>(basis_.size() - 1));
  }
}

template <class D>
typename Engine<D>::P Engine<D>::normalForm(P f, Coeff* scale) {
  bucket_.clear();
  bucket_.add(std::move(f));
  if (scale) *scale = Coeff(1);
  return reduce(P{}, 0, scale);
}

template class Engine<IntegerDomain>;
template class Engine<FmpzDomain>;
template class Engine<ModularDomain>;

}  // namespace sdfwb::algebra::gb
