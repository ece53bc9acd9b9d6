#pragma once
// Polynomial systems shared by the algebra tests and the benchmark: classic
// benchmark families (Katsura, cyclic) and small textbook systems.

#include "algebra/ideal.h"

#include <string>
#include <vector>

namespace sdfwb::algebra::testing {

struct NamedSystem {
  std::string name;
  Ideal ideal;
};

/// Katsura-n: n+1 unknowns u0..un, zero-dimensional with 2^n solutions.
Ideal katsura(int n, const MonomialOrder& order = MonomialOrder::degrevlex());
/// Cyclic-n roots.
Ideal cyclic(int n, const MonomialOrder& order = MonomialOrder::degrevlex());

/// Small systems with several orders, fast enough for unit tests.
std::vector<NamedSystem> small_systems();

}  // namespace sdfwb::algebra::testing
