#pragma once
// Internal to the Groebner engine: the record of a Buchberger run that the
// modular method replays modulo later primes.

#include "algebra/gb_layout.h"

#include <cstdint>
#include <vector>

namespace sdfwb::algebra::gb {

/// The useful steps of one Buchberger run: which pair (or input generator)
/// produced each new basis element, and its leading monomial. Modulo
/// another (lucky) prime the same steps produce the same leading monomials,
/// so a replay skips every pair that reduced to zero (Traverso's Groebner
/// trace algorithm, "Groebner trace algorithms", 1989).
struct Trace {
  struct Step {
    std::uint32_t i, j;  // basis indices, or j == generator marker: input generator i
    std::vector<Word> lead;
  };
  std::vector<Step> steps;
};

}  // namespace sdfwb::algebra::gb
