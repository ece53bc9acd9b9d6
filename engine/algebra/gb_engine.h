#pragma once
// Internal to the Groebner engine: Buchberger's algorithm on packed
// polynomials, generic over the coefficient domain.
//
// - Critical pairs are chosen by the sugar strategy (Giovini, Mora, Niesi,
//   Robbiano, Traverso 1991): smallest sugar first, then smallest lcm.
// - Useless pairs are removed by Gebauer and Moeller's installation of
//   Buchberger's criteria (product and chain criteria; "Installation of
//   Buchberger's algorithm", 1988), as in Becker-Weispfenning's UPDATE.
// - Input generators enter through the same queue as pairs (with their own
//   degree as sugar), so they are reduced against what is already known.
// - Reduction is full (lead and tail) in a geobucket; the final basis is
//   interreduced. Results are normalized by the domain (primitive integer
//   polynomials with positive leading coefficient, or monic mod p) and sorted
//   by increasing leading monomial.

#include "algebra/budget.h"
#include "algebra/gb_bucket.h"
#include "algebra/gb_trace.h"
#include "algebra/groebner_stats.h"

#include <optional>
#include <vector>

namespace sdfwb::algebra::gb {

template <class Domain>
class Engine {
 public:
  using Coeff = typename Domain::Coeff;
  using P = Poly<Coeff>;

  Engine(const Layout& layout, const Domain& domain, BudgetMonitor& monitor);

  /// The reduced Groebner basis of the input (zero polynomials ignored).
  /// Throws BudgetExceeded at a safe point when the budget runs out.
  /// If `record` is given, the useful steps are recorded into it. With
  /// `reduceTails` false the basis is minimal but its tails are not
  /// interreduced: for callers that keep part of it and reduce that.
  std::vector<P> groebner(std::vector<P> input, Trace* record = nullptr, bool reduceTails = true);

  /// The reduced basis from the steps of a trace recorded for the same
  /// input modulo another prime; nullopt as soon as a step does not give the
  /// recorded leading monomial (the trace does not fit this prime). The
  /// result is only as good as the trace: the modular algorithm verifies
  /// what it lifts. `reduceTails` as for groebner.
  std::optional<std::vector<P>> replay(std::vector<P> input, const Trace& trace, bool reduceTails = true);

  /// True if `basis` (nonzero, normalized polynomials) is a Groebner basis:
  /// every S-pair that survives the criteria reduces to zero. Use on a fresh
  /// engine.
  bool isGroebner(std::vector<P> basis);

  /// The reduced Groebner basis from a Groebner basis (not necessarily
  /// minimal or reduced): drops elements with a divisible leading monomial
  /// and reduces the tails.
  std::vector<P> reduceBasis(std::vector<P> basis);

  /// Installs a basis that is already a (reduced or not) Groebner basis, for
  /// normalForm.
  void setBasis(std::vector<P> basis);
  /// Full normal form of f with respect to the installed basis. Normalized
  /// by the domain, unless `scale` is given: then the result is scale * NF(f)
  /// exactly, with the accumulated factor stored in *scale.
  P normalForm(P f, Coeff* scale = nullptr);

  const GroebnerStats& stats() const { return stats_; }

 private:
  struct Element {
    P poly;
    std::uint64_t mask;
    bool redundant = false;
  };
  struct Pair {
    std::uint32_t i, j;  // j == kGenerator: input generator i
    std::uint32_t sugar;
    std::size_t lcm;  // offset into lcmStore_
    std::uint64_t mask;  // divmask of the lcm
    bool alive = true;
  };
  static constexpr std::uint32_t kGenerator = 0xffffffffu;  // also Trace::Step::j
  static constexpr std::size_t kContentBits = 64;

  const Word* lead(std::uint32_t element) const { return basis_[element].poly.mons.data(); }
  const Word* pairLcm(const Pair& pair) const { return lcmStore_.data() + pair.lcm; }
  int findReducer(const Word* mon, std::uint64_t mask) const;
  /// Reduces the bucket completely; `result` holds terms already final.
  P reduce(P result, std::uint32_t sugar, Coeff* scaleProduct = nullptr);
  /// Clears the bucket and loads the S-polynomial of elements i and j.
  void loadSPolynomial(std::uint32_t i, std::uint32_t j, const Word* lcm);
  /// Normalizes the input generators and sets their sugar.
  void loadGenerators(std::vector<P>& input);
  /// Interreduces (unless told not to) and returns the non-redundant
  /// elements, sorted.
  std::vector<P> finish(bool reduceTails = true);
  /// Divides the polynomial under reduction (result and bucket) by its content.
  void removeContent(P& result);
  void insert(P h);
  void pushPair(std::uint32_t i, std::uint32_t j, std::uint32_t sugar, const Word* lcm);
  bool pairBefore(std::uint32_t a, std::uint32_t b) const;
  /// Takes the best live pair off the heap (nullopt when none is left),
  /// counting it and checking the budget at `stage`.
  std::optional<Pair> nextPair(const char* stage);
  void interreduce();
  Progress progress(const char* stage) const;
  std::size_t ownBytes() const;

  const Layout& layout_;
  const Domain& domain_;
  BudgetMonitor& monitor_;
  Bucket<Domain> bucket_;
  std::vector<Element> basis_;
  std::vector<std::uint32_t> reducers_;  // indices of non-redundant elements
  std::vector<P> generators_;
  std::vector<Pair> pairs_;
  std::vector<Word> lcmStore_;
  std::vector<std::uint32_t> heap_;  // pair indices, best on top
  std::vector<Word> leadTerm_, shift_;  // reduce's scratch monomials
  std::size_t livePairs_ = 0;
  std::size_t basisBytes_ = 0;
  GroebnerStats stats_;
};

extern template class Engine<IntegerDomain>;
extern template class Engine<FmpzDomain>;
extern template class Engine<ModularDomain>;

}  // namespace sdfwb::algebra::gb
