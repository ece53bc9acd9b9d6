#include "algebra/gb_fglm.h"

#include "algebra/gb_convert.h"
#include "algebra/gb_engine.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>

namespace sdfwb::algebra::gb {

namespace {

using Exponents = std::vector<Word>;

Exponents exponentsOf(const Layout& layout, const Word* mon) {
  return Exponents(layout.exponents(mon), layout.exponents(mon) + layout.vars());
}

bool divisibleByAny(const Exponents& m, const std::vector<Exponents>& leads) {
  for (const Exponents& lead : leads) {
    bool divides = true;
    for (std::size_t v = 0; v < m.size() && divides; ++v) divides = lead[v] <= m[v];
    if (divides) return true;
  }
  return false;
}

// Standard monomials of the leads, each with its index.
std::map<Exponents, std::size_t> staircase(const std::vector<Exponents>& leads, std::size_t vars,
                                           BudgetMonitor& monitor) {
  std::map<Exponents, std::size_t> index;
  std::vector<Exponents> queue;
  Exponents one(vars, 0);
  if (divisibleByAny(one, leads)) return index;
  index.emplace(one, 0);
  queue.push_back(one);
  for (std::size_t next = 0; next < queue.size(); ++next) {
    for (std::size_t v = 0; v < vars; ++v) {
      Exponents m = queue[next];
      ++m[v];
      if (index.count(m) || divisibleByAny(m, leads)) continue;
      index.emplace(m, index.size());
      queue.push_back(std::move(m));
    }
    Progress progress;
    progress.stage = "fglm staircase";
    monitor.tick(progress, index.size() * vars * sizeof(Word));
  }
  return index;
}

void toPacked(const Layout& layout, const Exponents& e, Word* out) {
  std::copy(e.begin(), e.end(), out + layout.keys());
  layout.encodeKeys(out);
}

}  // namespace

std::optional<std::size_t> staircaseSize(const Layout& layout, const std::vector<const Word*>& leads) {
  std::vector<Exponents> leadExponents;
  for (const Word* lead : leads) leadExponents.push_back(exponentsOf(layout, lead));
  if (std::any_of(leadExponents.begin(), leadExponents.end(),
                  [](const Exponents& e) { return std::all_of(e.begin(), e.end(), [](Word x) { return x == 0; }); })) {
    return 0;  // the unit ideal: the quotient is 0
  }
  for (std::size_t v = 0; v < layout.vars(); ++v) {
    bool pure = false;
    for (const Exponents& e : leadExponents) {
      bool onlyV = e[v] > 0;
      for (std::size_t w = 0; w < layout.vars() && onlyV; ++w) onlyV = w == v || e[w] == 0;
      pure = pure || onlyV;
    }
    if (!pure) return std::nullopt;
  }
  const Budget unlimited;
  BudgetMonitor monitor(unlimited);
  return staircase(leadExponents, layout.vars(), monitor).size();
}

std::optional<MultiplicationTable> multiplicationTable(const Layout& source, const std::vector<Poly<mpz_class>>& basis,
                                                        BudgetMonitor& monitor) {
  std::vector<const Word*> leads;
  for (const Poly<mpz_class>& g : basis) leads.push_back(g.mons.data());
  if (!staircaseSize(source, leads)) return std::nullopt;
  const std::size_t vars = source.vars();
  std::vector<Exponents> leadExponents;
  for (const Word* lead : leads) leadExponents.push_back(exponentsOf(source, lead));
  const std::map<Exponents, std::size_t> index = staircase(leadExponents, vars, monitor);

  MultiplicationTable table;
  table.vars = vars;
  table.stairs.resize(index.size());
  for (const auto& [e, i] : index) table.stairs[i] = e;
  const std::size_t dim = table.dim();
  table.columns.resize(vars * dim);

  // The normal forms run on FLINT integers (see FmpzDomain): on GMP
  // integers allocated per term they were a seventh of Cyclic-5 in lex.
  const FmpzDomain integers;
  Engine<FmpzDomain> reducer(source, integers, monitor);
  std::vector<FmpzPoly> packedBasis;
  for (const Poly<mpz_class>& g : basis) packedBasis.push_back(toFmpzPoly(g));
  reducer.setBasis(std::move(packedBasis));
  Fmpz denominator;
  std::vector<Word> packed(source.stride());
  std::size_t bytes = 0;
  for (std::size_t b = 0; b < dim; ++b) {
    for (std::size_t v = 0; v < vars; ++v) {
      Exponents m = table.stairs[b];
      ++m[v];
      MultiplicationTable::Column& column = table.columns[v * dim + b];
      auto found = index.find(m);
      if (found != index.end()) {
        column.rows.push_back(static_cast<std::uint32_t>(found->second));
        column.numerators.emplace_back(1);
        continue;
      }
      FmpzPoly monomial;
      toPacked(source, m, packed.data());
      monomial.push(packed.data(), source.stride(), Fmpz(1));
      // normalForm with a scale returns scale * NF exactly.
      FmpzPoly nf = reducer.normalForm(std::move(monomial), &denominator);
      fmpz_get_mpz(column.denominator.get_mpz_t(), denominator.v);
      for (std::size_t t = 0; t < nf.size(); ++t) {
        column.rows.push_back(static_cast<std::uint32_t>(index.at(exponentsOf(source, nf.mon(t, source.stride())))));
        fmpz_get_mpz(column.numerators.emplace_back().get_mpz_t(), nf.coeffs[t].v);
      }
      bytes += column.rows.size() * (sizeof(std::uint32_t) + sizeof(mpz_class));
      Progress progress;
      progress.stage = "fglm matrices";
      monitor.tick(progress, bytes);
    }
  }
  return table;
}

namespace {

// An exact normal form: vector / denominator, with integer entries.
struct ExactVector {
  std::vector<mpz_class> entries;
  mpz_class denominator = 1;
};

// Divides entries and denominator by their common content.
void removeContent(ExactVector& v) {
  mpz_class g = v.denominator;
  for (const mpz_class& e : v.entries) {
    if (g == 1) return;
    if (sgn(e) != 0) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), e.get_mpz_t());
  }
  if (g == 1) return;
  for (mpz_class& e : v.entries) mpz_divexact(e.get_mpz_t(), e.get_mpz_t(), g.get_mpz_t());
  mpz_divexact(v.denominator.get_mpz_t(), v.denominator.get_mpz_t(), g.get_mpz_t());
}

}  // namespace

bool allInIdeal(const MultiplicationTable& table, const Layout& target, const std::vector<Poly<mpz_class>>& candidate,
                  BudgetMonitor& monitor) {
  const std::size_t vars = table.vars;
  const std::size_t dim = table.dim();
  if (dim == 0) return true;  // the unit ideal contains everything
  // Integer matrices N_v = D_v * M_v, D_v the lcm of the column denominators.
  std::vector<mpz_class> scale(vars, 1);
  for (std::size_t v = 0; v < vars; ++v) {
    for (std::size_t b = 0; b < dim; ++b) {
      const mpz_class& d = table.columns[v * dim + b].denominator;
      mpz_lcm(scale[v].get_mpz_t(), scale[v].get_mpz_t(), d.get_mpz_t());
    }
  }
  std::map<Exponents, ExactVector> cache;
  ExactVector one;
  one.entries.assign(dim, 0);
  one.entries[0] = 1;
  cache.emplace(Exponents(vars, 0), std::move(one));
  std::size_t bytes = 0;
  Progress progress;
  progress.stage = "fglm verification";
  // NF(m) = M_v * NF(m / x_v) for the last variable v of m, so that powers
  // of one variable share their chain of parents.
  std::function<const ExactVector&(const Exponents&)> normalForm = [&](const Exponents& m) -> const ExactVector& {
    auto found = cache.find(m);
    if (found != cache.end()) return found->second;
    std::size_t v = vars;
    while (m[v - 1] == 0) --v;
    --v;
    Exponents parentExponents = m;
    --parentExponents[v];
    const ExactVector& parent = normalForm(parentExponents);
    ExactVector out;
    out.entries.assign(dim, 0);
    mpz_class factor;
    for (std::size_t b = 0; b < dim; ++b) {
      if (sgn(parent.entries[b]) == 0) continue;
      const MultiplicationTable::Column& column = table.columns[v * dim + b];
      mpz_divexact(factor.get_mpz_t(), scale[v].get_mpz_t(), column.denominator.get_mpz_t());
      factor *= parent.entries[b];
      for (std::size_t k = 0; k < column.rows.size(); ++k) {
        mpz_addmul(out.entries[column.rows[k]].get_mpz_t(), factor.get_mpz_t(), column.numerators[k].get_mpz_t());
      }
    }
    out.denominator = parent.denominator * scale[v];
    removeContent(out);
    for (const mpz_class& e : out.entries) bytes += mpz_size(e.get_mpz_t()) * sizeof(mp_limb_t);
    monitor.check(progress, bytes);
    return cache.emplace(m, std::move(out)).first->second;
  };

  for (const Poly<mpz_class>& l : candidate) {
    // sum c_t NF(t) = 0  <=>  sum c_t (L / d_t) w_t = 0 with L = lcm d_t.
    mpz_class common = 1;
    std::vector<const ExactVector*> forms;
    for (std::size_t t = 0; t < l.size(); ++t) {
      const Word* e = target.exponents(l.mon(t, target.stride()));
      forms.push_back(&normalForm(Exponents(e, e + vars)));
      mpz_lcm(common.get_mpz_t(), common.get_mpz_t(), forms.back()->denominator.get_mpz_t());
    }
    std::vector<mpz_class> sum(dim, 0);
    mpz_class factor;
    for (std::size_t t = 0; t < l.size(); ++t) {
      mpz_divexact(factor.get_mpz_t(), common.get_mpz_t(), forms[t]->denominator.get_mpz_t());
      factor *= l.coeffs[t];
      for (std::size_t r = 0; r < dim; ++r) {
        if (sgn(forms[t]->entries[r]) != 0) {
          mpz_addmul(sum[r].get_mpz_t(), factor.get_mpz_t(), forms[t]->entries[r].get_mpz_t());
        }
      }
      // dim products of big integers per term, with no check above when the
      // term's normal form was cached.
      monitor.tick(progress, bytes);
    }
    for (const mpz_class& x : sum) {
      if (sgn(x) != 0) return false;
    }
  }
  return true;
}

std::optional<std::vector<ModPoly>> fglmModulo(const MultiplicationTable& table, const Layout& target,
                                                const ModularDomain& domain, BudgetMonitor& monitor) {
  const std::size_t vars = table.vars;
  const std::size_t dim = table.dim();
  const std::uint32_t p = domain.p;
  const std::size_t strideT = target.stride();
  if (dim == 0) {  // the unit ideal
    ModPoly one;
    std::vector<Word> m(strideT, 0);
    one.push(m.data(), strideT, 1);
    return std::vector<ModPoly>{one};
  }

  // The table modulo p: a pass over every exact numerator, repeated for
  // each prime, so it checks the budget too.
  struct Entry {
    std::uint32_t row, value;
  };
  const std::size_t matrixBytes = vars * dim * sizeof(Entry);
  Progress progress;
  progress.stage = "fglm";
  // Each column's residues are scaled by the inverse denominator at once
  // (Shoup's multiplication, ModularDomain::mulAll) into a column reserved
  // at its size: a division per entry and the growth of the columns were a
  // third of this function on Katsura-5 in lex (95 FGLM primes).
  std::vector<std::vector<Entry>> matrix(table.columns.size());
  std::vector<std::uint32_t> residues;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    monitor.tick(progress, matrixBytes);
    const MultiplicationTable::Column& column = table.columns[c];
    const auto den = static_cast<std::uint32_t>(mpz_fdiv_ui(column.denominator.get_mpz_t(), p));
    if (den == 0) return std::nullopt;
    residues.resize(column.rows.size());
    for (std::size_t k = 0; k < column.rows.size(); ++k) {
      residues[k] = static_cast<std::uint32_t>(mpz_fdiv_ui(column.numerators[k].get_mpz_t(), p));
    }
    domain.mulAll(residues.data(), residues.data(), residues.size(), domain.inverse(den));
    matrix[c].reserve(column.rows.size());
    for (std::size_t k = 0; k < column.rows.size(); ++k) {
      if (residues[k] != 0) matrix[c].push_back({column.rows[k], residues[k]});
    }
  }

  // Walk the monomials in increasing target order.
  struct Row {
    std::vector<std::uint32_t> vector;       // normalized: 1 at pivot
    std::vector<std::uint32_t> combination;  // over the new staircase
    std::size_t pivot;
  };
  std::vector<Row> rows;
  std::vector<Exponents> newStairs;
  std::vector<std::vector<std::uint32_t>> newStairVectors;
  std::vector<Exponents> newLeads;
  std::vector<ModPoly> result;

  auto packed = [&](const Exponents& e) {
    std::vector<Word> w(strideT);
    toPacked(target, e, w.data());
    return w;
  };
  auto byTargetOrder = [&](const std::vector<Word>& a, const std::vector<Word>& b) {
    return target.compare(a.data(), b.data()) < 0;
  };
  // Candidates (packed in the target layout) with the staircase element and
  // variable they come from.
  std::map<std::vector<Word>, std::pair<std::size_t, std::size_t>, decltype(byTargetOrder)> candidates(
      byTargetOrder);
  candidates.emplace(packed(Exponents(vars, 0)), std::make_pair(SIZE_MAX, 0));

  while (!candidates.empty()) {
    const std::vector<Word> mPacked = candidates.begin()->first;
    const auto origin = candidates.begin()->second;
    candidates.erase(candidates.begin());
    const Exponents m(target.exponents(mPacked.data()), target.exponents(mPacked.data()) + vars);
    if (divisibleByAny(m, newLeads)) continue;
    progress.basisSize = result.size();
    progress.pairsLeft = candidates.size();
    monitor.tick(progress, matrixBytes + rows.size() * 2 * dim * sizeof(std::uint32_t));

    // v = normal form of m, as M_var * NF(parent).
    std::vector<std::uint32_t> v(dim, 0);
    if (origin.first == SIZE_MAX) {
      v[0] = 1;  // stairs[0] is the monomial 1
    } else {
      const std::vector<std::uint32_t>& parent = newStairVectors[origin.first];
      // Products are below 2^62, so an accumulator below p takes three more
      // before it must be reduced.
      std::vector<std::uint64_t> acc(dim, 0);
      std::vector<std::uint8_t> pending(dim, 0);
      for (std::size_t b = 0; b < dim; ++b) {
        if (parent[b] == 0) continue;
        const std::uint64_t factor = parent[b];
        for (const Entry& e : matrix[origin.second * dim + b]) {
          acc[e.row] += factor * e.value;
          if (++pending[e.row] == 3) {
            acc[e.row] %= p;
            pending[e.row] = 0;
          }
        }
      }
      for (std::size_t r = 0; r < dim; ++r) v[r] = static_cast<std::uint32_t>(acc[r] % p);
    }
    const std::vector<std::uint32_t> normalForm = v;

    // Reduce by the echelon rows, tracking v = NF(m) - sum a_j NF(S_j).
    std::vector<std::uint32_t> a(newStairs.size(), 0);
    for (const Row& row : rows) {
      const std::uint32_t f = v[row.pivot];
      if (f == 0) continue;
      for (std::size_t r = 0; r < dim; ++r) {
        if (row.vector[r] == 0) continue;
        std::uint32_t t;
        domain.mul(t, f, row.vector[r]);
        v[r] = v[r] >= t ? v[r] - t : v[r] + (p - t);
      }
      for (std::size_t j = 0; j < row.combination.size(); ++j) {
        if (row.combination[j] == 0) continue;
        std::uint32_t t;
        domain.mul(t, f, row.combination[j]);
        domain.add(a[j], t);
      }
    }
    auto pivot = std::find_if(v.begin(), v.end(), [](std::uint32_t c) { return c != 0; });
    if (pivot == v.end()) {
      // NF(m) = sum a_j NF(S_j): m - sum a_j S_j is in the ideal.
      std::vector<std::pair<std::vector<Word>, std::uint32_t>> terms;
      for (std::size_t j = 0; j < a.size(); ++j) {
        if (a[j] != 0) terms.emplace_back(packed(newStairs[j]), p - a[j]);
      }
      std::sort(terms.begin(), terms.end(), [&](const auto& x, const auto& y) { return byTargetOrder(y.first, x.first); });
      ModPoly g;
      g.push(mPacked.data(), strideT, 1);
      for (auto& [w, c] : terms) g.push(w.data(), strideT, std::uint32_t{c});
      result.push_back(std::move(g));
      newLeads.push_back(m);
      continue;
    }
    // A new standard monomial; record the normalized row.
    const std::size_t index = newStairs.size();
    if (index >= dim) throw std::logic_error("fglm: staircase larger than the quotient's dimension");
    newStairs.push_back(m);
    newStairVectors.push_back(normalForm);
    Row row;
    row.pivot = static_cast<std::size_t>(pivot - v.begin());
    const std::uint32_t inverse = domain.inverse(v[row.pivot]);
    row.vector = std::move(v);
    for (std::uint32_t& c : row.vector) domain.mul(c, c, inverse);
    row.combination.assign(index + 1, 0);
    for (std::size_t j = 0; j < a.size(); ++j) {
      const std::uint32_t negated = a[j] == 0 ? 0 : p - a[j];
      domain.mul(row.combination[j], negated, inverse);
    }
    row.combination[index] = inverse;
    rows.push_back(std::move(row));
    for (std::size_t var = 0; var < vars; ++var) {
      Exponents next = m;
      ++next[var];
      candidates.emplace(packed(next), std::make_pair(index, var));
    }
  }
  return result;
}

}  // namespace sdfwb::algebra::gb
