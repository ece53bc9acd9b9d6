#pragma once
// Internal: elimination ideals by the modular method, lifting only the
// elimination part.
//
// The ideal is homogenized and its basis computed modulo primes for the
// order "total degree; then the degree in the eliminated variables; then
// degrevlex on them; then the remaining order; then h". Of each prime's
// basis only the elements free of the eliminated variables are kept,
// dehomogenized and reduced: the reduced basis of the elimination ideal
// modulo p. Only that (usually tiny) basis is lifted to Q, and it is
// verified by `contains` (exact membership in the ideal) and by checking
// that it is a Groebner basis, instead of verifying the whole basis of the
// homogenized ideal over Q, which costs far more than everything else.

#include "algebra/budget.h"
#include "algebra/groebner_stats.h"
#include "algebra/ideal.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::algebra::gb {

/// Reduced Groebner basis of I ∩ Q[remaining variables], in `remaining` (a
/// ring of the variables of I's ring not in `eliminated`, with the order
/// wanted for the result). `contains` must decide exactly whether a
/// polynomial of `remaining` lies in I. Throws BudgetExceeded.
/// `order`, if given, is the elimination order of I's variables (the
/// eliminated ones first) used modulo p in place of the block order above,
/// e.g. pure lex for the textbook's elimination; still only the
/// elimination part is lifted and verified.
std::vector<Polynomial> modularElimination(const Ideal& ideal, const std::vector<std::string>& eliminated,
                                            const RingPtr& remaining,
                                            const std::function<bool(const Polynomial&)>& contains,
                                            BudgetMonitor& monitor, GroebnerStats& stats,
                                            const std::optional<MonomialOrder>& order = std::nullopt);

}  // namespace sdfwb::algebra::gb
