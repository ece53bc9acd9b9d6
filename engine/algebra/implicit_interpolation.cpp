#include "algebra/implicit_interpolation.h"

#include <flint/fmpq.h>
#include <flint/fmpz.h>
#include <flint/nmod_mat.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <memory>
#include <random>
#include <thread>

namespace sdfwb::algebra {

namespace {

// ---- FLINT values with owners --------------------------------------------

struct Fmpz {
  fmpz_t v;
  Fmpz() { fmpz_init(v); }
  Fmpz(const Fmpz& other) { fmpz_init_set(v, other.v); }
  Fmpz& operator=(const Fmpz& other) {
    fmpz_set(v, other.v);
    return *this;
  }
  ~Fmpz() { fmpz_clear(v); }
};

struct Fmpq {
  fmpq_t v;
  Fmpq() { fmpq_init(v); }
  Fmpq(const Fmpq& other) {
    fmpq_init(v);
    fmpq_set(v, other.v);
  }
  Fmpq& operator=(const Fmpq& other) {
    fmpq_set(v, other.v);
    return *this;
  }
  ~Fmpq() { fmpq_clear(v); }
};

struct NmodMat {
  nmod_mat_t m;
  NmodMat(slong rows, slong cols, mp_limb_t p) { nmod_mat_init(m, rows, cols, p); }
  NmodMat(const NmodMat&) = delete;
  NmodMat& operator=(const NmodMat&) = delete;
  ~NmodMat() { nmod_mat_clear(m); }
};

// ---- The parametrization as integer polynomials ----------------------------

// One polynomial in the parameters with integer coefficients.
struct IntegerPoly {
  std::vector<std::vector<Exponent>> exponents;
  std::vector<Fmpz> coefficients;
};

// (W, X_1, ..., X_n): the homogeneous coordinates of the image point, over
// one denominator and scaled together to integer coefficients.
struct Homogeneous {
  std::size_t parameters = 0;
  std::vector<IntegerPoly> polys;
  std::vector<Exponent> maxDegree;  // per parameter, over all polys
  std::uint64_t totalDegree = 0;    // over all polys
};

Homogeneous homogeneousForm(const ClearedParametrization& c) {
  std::vector<const Polynomial*> all{&c.common};
  for (const Polynomial& s : c.scaled) all.push_back(&s);
  Integer den = 1;
  for (const Polynomial* f : all) {
    for (const Term& t : f->terms()) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), t.coefficient.get_den_mpz_t());
  }
  Homogeneous h;
  h.parameters = c.ring->size();
  h.maxDegree.assign(h.parameters, 0);
  for (const Polynomial* f : all) {
    IntegerPoly poly;
    for (const Term& t : f->terms()) {
      Rational scaled = t.coefficient * den;
      Fmpz coefficient;
      fmpz_set_mpz(coefficient.v, scaled.get_num_mpz_t());
      poly.coefficients.push_back(coefficient);
      poly.exponents.push_back(t.monomial.exponents());
      for (std::size_t v = 0; v < h.parameters; ++v) h.maxDegree[v] = std::max(h.maxDegree[v], t.monomial[v]);
    }
    h.totalDegree = std::max(h.totalDegree, f->totalDegree());
    h.polys.push_back(std::move(poly));
  }
  return h;
}

// deg(image) * deg(map) is at most this (see the header); saturates.
std::uint64_t degreeBound(const Homogeneous& h) {
  constexpr std::uint64_t kHuge = std::uint64_t{1} << 40;
  std::uint64_t bezout = 1, multi = 1;
  for (std::size_t v = 0; v < h.parameters; ++v) {
    bezout = std::min(kHuge, bezout * h.totalDegree);
    multi = std::min(kHuge, multi * h.maxDegree[v] * (v + 1));
  }
  return std::min(bezout, multi);
}

// ---- Monomials of one degree ------------------------------------------------

// Every exponent vector of total degree `degree` in `variables` variables, in
// a fixed order (the same for every prime).
std::vector<std::vector<Exponent>> monomialsOfDegree(std::size_t variables, Exponent degree) {
  std::vector<std::vector<Exponent>> out;
  std::vector<Exponent> e(variables, 0);
  auto fill = [&](auto&& self, std::size_t v, Exponent left) -> void {
    if (v + 1 == variables) {
      e[v] = left;
      out.push_back(e);
      return;
    }
    for (Exponent k = 0; k <= left; ++k) {
      e[v] = k;
      self(self, v + 1, left - k);
    }
  };
  fill(fill, 0, degree);
  return out;
}

std::size_t monomialCount(std::size_t variables, std::uint64_t degree) {
  // C(degree + variables - 1, variables - 1), saturating far above any limit.
  double count = 1;
  for (std::size_t i = 1; i < variables; ++i) count = count * static_cast<double>(degree + i) / static_cast<double>(i);
  return count > 1e15 ? std::size_t{1} << 50 : static_cast<std::size_t>(count + 0.5);
}

// ---- Modulo one prime ---------------------------------------------------------

// The nullspace modulo p at one degree, normalized (see the header).
struct PrimeImage {
  mp_limb_t prime = 0;
  slong nullity = 0;
  slong lastNonzero = -1;          // normalization index when nullity == 1
  std::vector<mp_limb_t> vector;    // when nullity == 1
};

mp_limb_t residue(const fmpz_t c, nmod_t mod) { return fmpz_fdiv_ui(c, mod.n); }

mp_limb_t evaluateMod(const IntegerPoly& f, const std::vector<std::vector<mp_limb_t>>& powers,
                       const std::vector<mp_limb_t>& coefficients, nmod_t mod) {
  mp_limb_t sum = 0;
  for (std::size_t t = 0; t < f.exponents.size(); ++t) {
    mp_limb_t term = coefficients[t];
    for (std::size_t v = 0; v < powers.size(); ++v) term = nmod_mul(term, powers[v][f.exponents[t][v]], mod);
    sum = nmod_add(sum, term, mod);
  }
  return sum;
}

PrimeImage nullspaceMod(const Homogeneous& h, const std::vector<std::vector<Exponent>>& monomials, Exponent degree,
                         mp_limb_t prime) {
  nmod_t mod;
  nmod_init(&mod, prime);
  const slong columns = static_cast<slong>(monomials.size());
  const slong rows = columns + 8;  // a few spare points against unlucky ones
  std::vector<std::vector<mp_limb_t>> coefficients(h.polys.size());
  for (std::size_t j = 0; j < h.polys.size(); ++j) {
    for (const Fmpz& c : h.polys[j].coefficients) coefficients[j].push_back(residue(c.v, mod));
  }
  std::mt19937_64 random(prime);
  std::vector<std::vector<mp_limb_t>> parameterPowers(h.parameters);
  std::vector<std::vector<mp_limb_t>> valuePowers(h.polys.size(), std::vector<mp_limb_t>(degree + 1));
  NmodMat matrix(rows, columns, prime);
  for (slong r = 0; r < rows; ++r) {
    for (std::size_t v = 0; v < h.parameters; ++v) {
      const mp_limb_t t = random() % prime;
      std::vector<mp_limb_t>& pw = parameterPowers[v];
      pw.assign(h.maxDegree[v] + 1, 1);
      for (std::size_t k = 1; k < pw.size(); ++k) pw[k] = nmod_mul(pw[k - 1], t, mod);
    }
    for (std::size_t j = 0; j < h.polys.size(); ++j) {
      const mp_limb_t value = evaluateMod(h.polys[j], parameterPowers, coefficients[j], mod);
      valuePowers[j][0] = 1;
      for (Exponent k = 1; k <= degree; ++k) valuePowers[j][k] = nmod_mul(valuePowers[j][k - 1], value, mod);
    }
    for (slong c = 0; c < columns; ++c) {
      mp_limb_t entry = 1;
      for (std::size_t j = 0; j < h.polys.size(); ++j) entry = nmod_mul(entry, valuePowers[j][monomials[c][j]], mod);
      nmod_mat_entry(matrix.m, r, c) = entry;
    }
  }
  NmodMat kernel(columns, columns, prime);
  PrimeImage image;
  image.prime = prime;
  image.nullity = nmod_mat_nullspace(kernel.m, matrix.m);
  if (image.nullity != 1) return image;
  image.vector.resize(static_cast<std::size_t>(columns));
  for (slong c = 0; c < columns; ++c) {
    image.vector[static_cast<std::size_t>(c)] = nmod_mat_entry(kernel.m, c, 0);
    if (image.vector[static_cast<std::size_t>(c)] != 0) image.lastNonzero = c;
  }
  const mp_limb_t inverse = n_invmod(image.vector[static_cast<std::size_t>(image.lastNonzero)], prime);
  for (mp_limb_t& x : image.vector) x = nmod_mul(x, inverse, mod);
  return image;
}

// ---- Chinese remaindering and rational reconstruction --------------------------

class Lifting {
 public:
  explicit Lifting(std::size_t size) : residues_(size) { fmpz_one(modulus_.v); }

  // r + M * ((c - r) / M mod p) for each residue r (mod M) and c (mod p),
  // with 1/M mod p computed once: fmpz_CRT_ui recomputes it for every
  // coefficient, which made it a fifth of a small implicitization.
  void add(const PrimeImage& image) {
    nmod_t mod;
    nmod_init(&mod, image.prime);
    const mp_limb_t mInverse = n_invmod(fmpz_fdiv_ui(modulus_.v, image.prime), image.prime);
    for (std::size_t i = 0; i < residues_.size(); ++i) {
      const mp_limb_t r = fmpz_fdiv_ui(residues_[i].v, image.prime);
      const mp_limb_t t = nmod_mul(nmod_sub(image.vector[i], r, mod), mInverse, mod);
      fmpz_addmul_ui(residues_[i].v, modulus_.v, t);
    }
    fmpz_mul_ui(modulus_.v, modulus_.v, image.prime);
    ++primes_;
  }
  std::size_t primes() const { return primes_; }

  // The rationals with small numerators and denominators congruent to the
  // residues, if every coefficient has one.
  bool reconstruct(std::vector<Fmpq>& out) const {
    out.resize(residues_.size());
    for (std::size_t i = 0; i < residues_.size(); ++i) {
      if (!fmpq_reconstruct_fmpz(out[i].v, residues_[i].v, modulus_.v)) return false;
    }
    return true;
  }

 private:
  std::vector<Fmpz> residues_;
  Fmpz modulus_;
  std::size_t primes_ = 0;
};

bool agrees(const std::vector<Fmpq>& candidate, const PrimeImage& image) {
  nmod_t mod;
  nmod_init(&mod, image.prime);
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    const mp_limb_t den = fmpz_fdiv_ui(fmpq_denref(candidate[i].v), image.prime);
    if (den == 0) return false;
    const mp_limb_t num = fmpz_fdiv_ui(fmpq_numref(candidate[i].v), image.prime);
    if (nmod_mul(num, n_invmod(den, image.prime), mod) != image.vector[i]) return false;
  }
  return true;
}

// Integer coefficients with gcd 1: the candidate times the lcm of its
// denominators, divided by the gcd of the results.
std::vector<Fmpz> primitiveIntegers(const std::vector<Fmpq>& candidate) {
  Fmpz den, g;
  fmpz_one(den.v);
  for (const Fmpq& c : candidate) fmpz_lcm(den.v, den.v, fmpq_denref(c.v));
  std::vector<Fmpz> out(candidate.size());
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    fmpz_divexact(out[i].v, den.v, fmpq_denref(candidate[i].v));
    fmpz_mul(out[i].v, out[i].v, fmpq_numref(candidate[i].v));
    fmpz_gcd(g.v, g.v, out[i].v);
  }
  for (Fmpz& c : out) fmpz_divexact(c.v, c.v, g.v);
  return out;
}

// ---- The exact check --------------------------------------------------------------

// F(W(t), X(t)) == 0 at every point of the grid described in the header,
// evaluated with exact integers. Points are centred on 0 to keep them small.
bool vanishesOnGrid(const Homogeneous& h, const std::vector<std::vector<Exponent>>& monomials,
                      const std::vector<Fmpz>& coefficients, Exponent degree, BudgetMonitor& monitor) {
  std::vector<std::uint64_t> extent(h.parameters);
  for (std::size_t v = 0; v < h.parameters; ++v) extent[v] = std::uint64_t{degree} * h.maxDegree[v] + 1;
  std::vector<std::uint64_t> index(h.parameters, 0);
  std::vector<std::vector<Fmpz>> parameterPowers(h.parameters);
  std::vector<std::vector<Fmpz>> valuePowers(h.polys.size(), std::vector<Fmpz>(degree + 1));
  Fmpz term, sum;
  Progress progress;
  progress.stage = "verification";
  for (;;) {
    monitor.check(progress);
    for (std::size_t v = 0; v < h.parameters; ++v) {
      std::vector<Fmpz>& pw = parameterPowers[v];
      pw.assign(h.maxDegree[v] + 1, Fmpz());
      fmpz_one(pw[0].v);
      const slong t = static_cast<slong>(index[v]) - static_cast<slong>(extent[v] / 2);
      for (std::size_t k = 1; k < pw.size(); ++k) fmpz_mul_si(pw[k].v, pw[k - 1].v, t);
    }
    for (std::size_t j = 0; j < h.polys.size(); ++j) {
      const IntegerPoly& f = h.polys[j];
      Fmpz value;
      for (std::size_t t = 0; t < f.exponents.size(); ++t) {
        fmpz_set(term.v, f.coefficients[t].v);
        for (std::size_t v = 0; v < h.parameters; ++v) fmpz_mul(term.v, term.v, parameterPowers[v][f.exponents[t][v]].v);
        fmpz_add(value.v, value.v, term.v);
      }
      fmpz_one(valuePowers[j][0].v);
      for (Exponent k = 1; k <= degree; ++k) fmpz_mul(valuePowers[j][k].v, valuePowers[j][k - 1].v, value.v);
    }
    fmpz_zero(sum.v);
    for (std::size_t c = 0; c < monomials.size(); ++c) {
      if (fmpz_is_zero(coefficients[c].v)) continue;
      fmpz_set(term.v, coefficients[c].v);
      for (std::size_t j = 0; j < h.polys.size(); ++j) fmpz_mul(term.v, term.v, valuePowers[j][monomials[c][j]].v);
      fmpz_add(sum.v, sum.v, term.v);
    }
    if (!fmpz_is_zero(sum.v)) return false;
    std::size_t v = 0;
    while (v < h.parameters && ++index[v] == extent[v]) index[v++] = 0;
    if (v == h.parameters) return true;
  }
}

Polynomial toPolynomial(const std::vector<std::vector<Exponent>>& monomials, const std::vector<Fmpz>& coefficients,
                         const RingPtr& ring, const std::vector<std::size_t>& coordinateIndex) {
  std::vector<Term> terms;
  for (std::size_t c = 0; c < monomials.size(); ++c) {
    if (fmpz_is_zero(coefficients[c].v)) continue;
    Monomial m(ring->size());
    for (std::size_t i = 0; i < coordinateIndex.size(); ++i) m[coordinateIndex[i]] = monomials[c][i + 1];
    Integer value;
    fmpz_get_mpz(value.get_mpz_t(), coefficients[c].v);
    terms.push_back({std::move(m), Rational(value)});
  }
  return Polynomial(ring, std::move(terms)).primitive();
}

std::size_t matrixBytes(std::size_t columns) { return 2 * (columns + 8) * columns * sizeof(mp_limb_t); }

using Monomials = std::vector<std::vector<Exponent>>;

// Below this many columns a nullspace takes a few milliseconds: it is
// computed on the calling thread (a thread would cost more than the wait for
// a cancel, and a batch of threads more primes than needed).
constexpr std::size_t kThreadedColumns = 256;

// One nullspace on a thread of its own (small ones inline, see above).
// FLINT's nmod_mat_nullspace cannot be interrupted, so the caller waits for
// it checking the budget, and on a cancel or a limit leaves it: the thread
// finishes that one matrix (it owns its inputs) and exits, while the
// computation reports at once.
std::future<PrimeImage> startNullspace(std::shared_ptr<const Homogeneous> h, std::shared_ptr<const Monomials> monomials,
                                        Exponent degree, mp_limb_t prime) {
  if (monomials->size() < kThreadedColumns) {
    std::promise<PrimeImage> ready;
    ready.set_value(nullspaceMod(*h, *monomials, degree, prime));
    return ready.get_future();
  }
  std::packaged_task<PrimeImage()> task(
      [h = std::move(h), monomials = std::move(monomials), degree, prime] {
        return nullspaceMod(*h, *monomials, degree, prime);
      });
  std::future<PrimeImage> result = task.get_future();
  std::thread(std::move(task)).detach();
  return result;
}

PrimeImage waitFor(std::future<PrimeImage>& image, BudgetMonitor& monitor, const Progress& progress,
                    std::size_t ownBytes) {
  while (image.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) monitor.check(progress, ownBytes);
  return image.get();
}

bool applies(const RationalParametrization& p) {
  return p.relations.empty() && p.parameters.size() + 1 == p.coordinates.size();
}

}  // namespace

std::optional<double> interpolationCost(const RationalParametrization& p) {
  if (!applies(p)) return std::nullopt;
  const Homogeneous h = homogeneousForm(clearDenominators(p));
  if (h.totalDegree == 0) return std::nullopt;
  const std::uint64_t bound = degreeBound(h);
  std::size_t columns = 1;
  for (std::uint64_t d = 1; d <= bound && columns <= kMaxInterpolationMonomials; ++d) {
    columns = monomialCount(h.polys.size(), d);
  }
  columns = std::min(columns, kMaxInterpolationMonomials);
  // The degree search costs about twice its last matrix (the sizes grow
  // like d^n), and the reconstruction takes at least two more primes.
  constexpr double kMatrices = 4;
  const double n = static_cast<double>(columns);
  return kMatrices * n * n * n / 3;
}

std::optional<Polynomial> implicitizeByInterpolation(const RationalParametrization& p, const RingPtr& coordinates,
                                                       BudgetMonitor& monitor, GroebnerStats& stats) {
  if (!applies(p)) return std::nullopt;
  const auto shared = std::make_shared<const Homogeneous>(homogeneousForm(clearDenominators(p)));
  const Homogeneous& h = *shared;
  if (h.totalDegree == 0) return std::nullopt;
  const std::size_t variables = h.polys.size();
  std::vector<std::size_t> coordinateIndex;
  for (const std::string& name : p.coordinates) coordinateIndex.push_back(*coordinates->indexOf(name));

  Progress progress;
  progress.stage = "interpolation";
  const std::uint64_t bound = degreeBound(h);
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  // Word primes above 2^62 - 2^40: nmod arithmetic takes up to 64 bits, and
  // fewer, larger primes mean fewer matrices.
  mp_limb_t prime = (mp_limb_t{1} << 62) - (mp_limb_t{1} << 40);
  auto nextPrime = [&] { return prime = n_nextprime(prime, 1); };

  // 1. The degree: the first nonzero nullspace of the search, modulo one
  // prime; a nullspace of dimension above 1 there is given one more prime.
  // Returns 0 when interpolation does not apply.
  PrimeImage first;
  auto searchDegree = [&]() -> Exponent {
    for (int attempt = 0; attempt < 2; ++attempt) {
      const mp_limb_t p0 = nextPrime();
      ++stats.primes;
      for (std::uint64_t d = 1; d <= bound; ++d) {
        const std::size_t columns = monomialCount(variables, d);
        if (columns > kMaxInterpolationMonomials) return 0;
        monitor.check(progress, matrixBytes(columns));
        const Exponent e = static_cast<Exponent>(d);
        std::future<PrimeImage> image =
            startNullspace(shared, std::make_shared<const Monomials>(monomialsOfDegree(variables, e)), e, p0);
        first = waitFor(image, monitor, progress, matrixBytes(columns));
        if (first.nullity == 1) return e;
        if (first.nullity > 1) break;
      }
      if (first.nullity == 0) return 0;  // no equation within the bound: not a hypersurface
    }
    return 0;
  };

  for (;;) {
    const Exponent degree = searchDegree();
    if (degree == 0) return std::nullopt;
    const auto sharedMonomials = std::make_shared<const Monomials>(monomialsOfDegree(variables, degree));
    const Monomials& monomials = *sharedMonomials;
    const unsigned batchSize = monomials.size() < kThreadedColumns ? 1 : workers;
    const std::size_t ownBytes = matrixBytes(monomials.size()) * batchSize;

    // 2.-4. More primes, a batch of one per worker at a time (one at a time
    // when they are computed inline), until a reconstruction agrees with a
    // fresh prime and passes the exact check.
    Lifting lifting(monomials.size());
    slong normalizedAt = first.lastNonzero;
    lifting.add(first);
    std::vector<Fmpq> candidate;
    bool haveCandidate = false, restart = false;
    while (!restart) {
      monitor.setPrimes(lifting.primes());
      monitor.check(progress, ownBytes);
      std::vector<std::future<PrimeImage>> batch;
      for (unsigned w = 0; w < batchSize; ++w) {
        batch.push_back(startNullspace(shared, sharedMonomials, degree, nextPrime()));
      }
      for (std::future<PrimeImage>& f : batch) {
        PrimeImage image = waitFor(f, monitor, progress, ownBytes);
        ++stats.primes;
        if (restart) continue;
        // A zero nullspace: the first prime's points were unlucky and its
        // degree too small. Search again.
        if (image.nullity == 0) restart = true;
        if (restart || image.nullity > 1 || image.lastNonzero < normalizedAt) continue;  // unlucky prime
        if (image.lastNonzero > normalizedAt) {
          // Every prime so far lost F's last coefficient: they were the unlucky ones.
          lifting = Lifting(monomials.size());
          normalizedAt = image.lastNonzero;
          haveCandidate = false;
        } else if (haveCandidate && agrees(candidate, image)) {
          const std::vector<Fmpz> integers = primitiveIntegers(candidate);
          if (vanishesOnGrid(h, monomials, integers, degree, monitor)) {
            return toPolynomial(monomials, integers, coordinates, coordinateIndex);
          }
          // Only a degree found too small gives a candidate that agrees
          // with a fresh prime and still fails: search again.
          restart = true;
          continue;
        }
        lifting.add(image);
        haveCandidate = lifting.reconstruct(candidate);
      }
    }
  }
}

}  // namespace sdfwb::algebra
