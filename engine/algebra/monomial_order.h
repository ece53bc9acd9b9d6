#pragma once
// Monomial orders: lex, deglex, degrevlex, weighted (weight vector plus a
// tie-break order) and block orders (the elimination orders).
//
// Variables are ranked by their index: variable 0 is the largest, as in
// "degrevlex with x > y > z" for the variable list (x, y, z).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::algebra {

using Exponent = std::uint32_t;

class MonomialOrder {
 public:
  enum class Kind { Lex, Deglex, Degrevlex, Weighted, Block };

  /// A block of `size` consecutive variables ordered by `order`.
  struct Block;

  // Out of line, as is the constructor: clang instantiates ~vector<Block>
  // where they are defined (and for the default argument below), and Block
  // is incomplete inside this class.
  ~MonomialOrder();
  MonomialOrder(const MonomialOrder&);
  MonomialOrder(MonomialOrder&&) noexcept;
  MonomialOrder& operator=(const MonomialOrder&);
  MonomialOrder& operator=(MonomialOrder&&) noexcept;

  static MonomialOrder lex();
  static MonomialOrder deglex();
  static MonomialOrder degrevlex();
  /// Compares the weighted degrees sum(w_i * e_i) first and breaks ties with
  /// `tieBreak`. Weights must be non-negative (so 1 stays the smallest
  /// monomial); `weights.size()` must equal the ring's variable count.
  static MonomialOrder weighted(std::vector<std::int64_t> weights,
                                const MonomialOrder& tieBreak = degrevlex());
  /// Block order: compares the first block's variables by its order, then the
  /// next block's, and so on. Block sizes must add up to the variable count.
  static MonomialOrder block(std::vector<Block> blocks);
  /// The usual elimination order: the first `eliminated` variables form a
  /// block ordered by `eliminatedOrder`, the rest by `restOrder`. Any
  /// monomial containing an eliminated variable is larger than every
  /// monomial free of them.
  static MonomialOrder elimination(std::size_t eliminated,
                                   const MonomialOrder& eliminatedOrder = degrevlex(),
                                   const MonomialOrder& restOrder = degrevlex());
  /// "lex", "deglex" or "degrevlex" (the names the CLI accepts).
  static std::optional<MonomialOrder> fromName(std::string_view name);

  Kind kind() const { return kind_; }
  const std::vector<std::int64_t>& weights() const { return weights_; }
  /// The tie-break order of a weighted order (requires kind() == weighted).
  const MonomialOrder& tieBreak() const { return tieBreak_.front(); }
  const std::vector<Block>& blocks() const { return blocks_; }

  /// Throws std::invalid_argument naming the mismatch when this order cannot
  /// order monomials in `variableCount` variables.
  void checkFits(std::size_t variableCount) const;

  /// The order as an integer matrix M (rows of length `variableCount`):
  /// a < b iff M*a < M*b lexicographically. Ring compares with it (except
  /// for the plain orders, which have faster paths), and the Groebner engine
  /// precomputes comparison keys M*e, which add under multiplication.
  std::vector<std::vector<std::int64_t>> matrix(std::size_t variableCount) const;

  /// Readable description, e.g. "degrevlex", "weighted(1,2,3; degrevlex)",
  /// "block(2: degrevlex, 3: lex)".
  std::string describe() const;

  friend bool operator==(const MonomialOrder& a, const MonomialOrder& b);

 private:
  explicit MonomialOrder(Kind kind);

  Kind kind_;
  std::vector<std::int64_t> weights_;  // weighted only
  std::vector<MonomialOrder> tieBreak_;  // weighted only: exactly one entry
  std::vector<Block> blocks_;             // block only
};

struct MonomialOrder::Block {
  std::size_t size;
  MonomialOrder order;
  friend bool operator==(const Block&, const Block&) = default;
};

}  // namespace sdfwb::algebra
