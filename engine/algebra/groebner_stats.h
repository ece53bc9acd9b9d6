#pragma once
// Counters a Groebner computation reports (for --json, benchmarks and tests).

#include <cstddef>

namespace sdfwb::algebra {

struct GroebnerStats {
  std::size_t pairsTreated = 0;        // S-polynomials (and generators) reduced
  std::size_t zeroReductions = 0;      // of those, how many reduced to 0
  std::size_t productCriterion = 0;    // pairs skipped: coprime leading monomials
  std::size_t chainCriterion = 0;      // pairs skipped: Gebauer-Moeller chain criterion
  std::size_t reductionSteps = 0;      // single reduction steps
  std::size_t maxBasisSize = 0;       // largest intermediate basis
  std::size_t contentRemovals = 0;     // common factors divided out during reductions
  std::size_t primes = 0;               // modular method: primes used
  std::size_t replays = 0;              // of those, computed by replaying a trace
  std::size_t verificationPairs = 0;   // modular method: S-pairs checked over Q
};

}  // namespace sdfwb::algebra
