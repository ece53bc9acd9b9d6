#pragma once
// Internal: the FGLM change of ordering (Faugere, Gianni, Lazard, Mora,
// "Efficient computation of zero-dimensional Groebner bases by change of
// ordering", 1993).
//
// Given the reduced basis G of a zero-dimensional ideal I in one order, the
// quotient Q[x]/I is a vector space with basis the standard monomials of G
// (the staircase), and multiplication by a variable is a matrix. FGLM walks
// the monomials in the target order, gets each one's normal form from the
// matrices, and finds the target basis as the first linear dependencies:
// linear algebra only, no S-polynomials, which is what makes lex bases of
// zero-dimensional systems cheap. The matrices are computed once over Q;
// the linear algebra runs modulo primes (see modularFglm).

#include "algebra/budget.h"
#include "algebra/gb_poly.h"

#include <optional>
#include <vector>

namespace sdfwb::algebra::gb {

/// The multiplication matrices of Q[x]/I over Q, column by column.
struct MultiplicationTable {
  std::size_t vars = 0;
  std::vector<std::vector<Word>> stairs;  // exponent vectors; stairs[0] is 1
  /// NF(x_v * stairs[b]) = sum numerators[k] * stairs[rows[k]] / denominator.
  struct Column {
    std::vector<std::uint32_t> rows;
    std::vector<mpz_class> numerators;
    mpz_class denominator = 1;
  };
  std::vector<Column> columns;  // index v * dim + b
  std::size_t dim() const { return stairs.size(); }
};

/// Number of standard monomials of the given leading monomials, or nullopt
/// when the ideal is not zero-dimensional (some variable has no pure power
/// among them).
std::optional<std::size_t> staircaseSize(const Layout& layout, const std::vector<const Word*>& leads);

/// The table of the ideal with reduced Groebner basis `basis` (integer
/// multiples of its elements, in `source`'s order); nullopt when the ideal is
/// not zero-dimensional. Checks the budget.
std::optional<MultiplicationTable> multiplicationTable(const Layout& source, const std::vector<Poly<mpz_class>>& basis,
                                                        BudgetMonitor& monitor);

/// Exact check over Q that every candidate polynomial (integer
/// coefficients, packed in `target`) has normal form 0, i.e. lies in the
/// ideal: normal forms of monomials come from the table, walking from 1 by
/// multiplication (fraction-free, content removed), never from S-polynomials.
bool allInIdeal(const MultiplicationTable& table, const Layout& target, const std::vector<Poly<mpz_class>>& candidate,
                  BudgetMonitor& monitor);

/// The reduced basis modulo domain.p in `target`'s order (monic, increasing
/// leading monomials); nullopt when p divides a denominator of the table.
std::optional<std::vector<ModPoly>> fglmModulo(const MultiplicationTable& table, const Layout& target,
                                                const ModularDomain& domain, BudgetMonitor& monitor);

}  // namespace sdfwb::algebra::gb
