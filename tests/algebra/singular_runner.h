#pragma once
// Test and benchmark support: runs Singular (a reference computer algebra
// system) on an ideal and reads back its reduced Groebner basis, so our
// results can be cross-checked and timed against it in the same run.

#include "algebra/ideal.h"

#include <optional>
#include <string>
#include <vector>

namespace sdfwb::algebra::testing {

/// Path of the Singular executable, or nullopt when it is not installed.
std::optional<std::string> singularPath();

struct SingularResult {
  bool ok = false;
  std::string error;               // why it failed (timeout, parse error, ...)
  std::vector<Polynomial> basis;   // monic, sorted by increasing leading monomial
  double seconds = 0;              // Singular's own wall-clock time for the command
  double cpuSeconds = 0;          // and its CPU time (each the mean of enough repetitions
                                   // for 100 ms of CPU: its timer counts in 10 ms steps)
};

/// Reduced Groebner basis by Singular (option redSB) in the ideal's ring and
/// order; `command` is "std", or "stdfglm" (degrevlex, then FGLM).
SingularResult singularStd(const Ideal& ideal, double timeoutSeconds = 60, const std::string& command = "std");

/// Generators of the elimination ideal I ∩ Q[remaining variables] by
/// Singular's eliminate, followed by a reduced std in `target` (a ring with
/// the remaining variables).
SingularResult singularEliminate(const Ideal& ideal, const std::vector<std::string>& eliminated,
                                  const RingPtr& target, double timeoutSeconds = 60);

/// Singular's order name for a ring, e.g. "dp", "lp", "(a(1,2),dp)",
/// "(dp(2),dp(3))"; nullopt for orders without a translation.
std::optional<std::string> singularOrder(const Ring& ring);

/// Parses Singular's printed polynomial ("v0^2*v1-1/2*v2+3", variables named
/// prefix + the ring's variable index).
Polynomial parseSingularPolynomial(const std::string& text, const RingPtr& ring, const char* prefix = "v");

}  // namespace sdfwb::algebra::testing
