#pragma once
// The monomial orders an implicitization can eliminate by, with the names the
// CLI and the polynomial panel offer. A file of its own, free of GMP and FLINT,
// so the command line can list them without loading the algebra.

#include <optional>
#include <span>
#include <string_view>

namespace sdfwb::algebra {

/// The monomial order of the elimination. Each is an elimination order (a
/// monomial with a parameter is larger than any monomial in the coordinates
/// alone), so each gives the same elimination ideal; the order on the
/// coordinates decides which reduced basis describes it when it needs several
/// generators (a curve), and the computation differs.
enum class EliminationOrder {
  /// Parameters in a degrevlex block above the coordinates, ordered by
  /// degrevlex: the fastest (the default).
  BlockDegrevlex,
  BlockDeglex,  // the coordinates by deglex
  BlockLex,     // the coordinates by lex
  /// Pure lex over the parameters, then the coordinates: Theorem 1.7 as the
  /// textbook states it. The whole ideal's lex basis is computed modulo
  /// primes (only its elimination part is lifted to Q), so this is the
  /// slowest; it never interpolates; its result equals BlockLex's.
  Lex,
};

struct EliminationOrderName {
  EliminationOrder order;
  std::string_view name;         // what --order takes: "elimination", "lex", ...
  std::string_view description;  // one line for menus and --help
};
/// Every choice, the default first.
std::span<const EliminationOrderName> eliminationOrders();
std::optional<EliminationOrder> eliminationOrderFromName(std::string_view name);

}  // namespace sdfwb::algebra
