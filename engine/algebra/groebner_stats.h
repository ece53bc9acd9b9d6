#pragma once
// Counters a Groebner computation reports (for --json, benchmarks and tests).

#include <cstddef>

namespace sdfwb::algebra {

struct GroebnerStats {
  std::size_t pairs_treated = 0;        // S-polynomials (and generators) reduced
  std::size_t zero_reductions = 0;      // of those, how many reduced to 0
  std::size_t product_criterion = 0;    // pairs skipped: coprime leading monomials
  std::size_t chain_criterion = 0;      // pairs skipped: Gebauer-Moeller chain criterion
  std::size_t reduction_steps = 0;      // single reduction steps
  std::size_t max_basis_size = 0;       // largest intermediate basis
  std::size_t content_removals = 0;     // common factors divided out during reductions
  std::size_t primes = 0;               // modular method: primes used
  std::size_t replays = 0;              // of those, computed by replaying a trace
  std::size_t verification_pairs = 0;   // modular method: S-pairs checked over Q
};

}  // namespace sdfwb::algebra
