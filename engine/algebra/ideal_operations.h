#pragma once
// Operations on ideals built on Groebner bases: membership, sum, product,
// intersection, elimination, radical membership.
//
// Operations that compute a Groebner basis take GroebnerOptions (budget,
// method) and report like groebnerBasis: a status and, when it gave up, a
// "gave up after ..." message instead of the value.

#include "algebra/groebner.h"

#include <string>
#include <vector>

namespace sdfwb::algebra {

/// A yes/no answer from a budgeted computation.
struct Decision {
  Status status = Status::Completed;
  std::string message;  // empty when completed
  bool value = false;   // meaningful only when completed
  double seconds = 0;

  bool ok() const { return status == Status::Completed; }
};

/// I + J: the generators of both (same ring required).
Ideal sum(const Ideal& i, const Ideal& j);
/// I * J: the pairwise products of generators (same ring required).
Ideal product(const Ideal& i, const Ideal& j);

/// f in I: f reduces to 0 by a Groebner basis of I.
Decision contains(const Ideal& ideal, const Polynomial& f, const GroebnerOptions& options = {});

/// f in the radical of I (some power of f lies in I): 1 is in
/// I + <1 - f*y> for a fresh variable y (Rabinowitsch trick).
Decision radicalContains(const Ideal& ideal, const Polynomial& f, const GroebnerOptions& options = {});

/// Reduced Groebner basis of I ∩ J, as the elimination of t from
/// t*I + (1 - t)*J (CLO 4.3 Theorem 11), in I's ring.
GroebnerResult intersection(const Ideal& i, const Ideal& j, const GroebnerOptions& options = {});

/// Reduced Groebner basis of the elimination ideal I ∩ Q[remaining
/// variables], computed with the block order (eliminated variables ordered by
/// degrevlex) > (remaining variables ordered by `remainingOrder`). The basis
/// lives in a new ring of the remaining variables, in their original order,
/// with `remainingOrder`. Throws std::invalid_argument for a name that is
/// not a variable of I's ring.
GroebnerResult eliminate(const Ideal& ideal, const std::vector<std::string>& variables,
                         const GroebnerOptions& options = {},
                         const MonomialOrder& remainingOrder = MonomialOrder::degrevlex());

}  // namespace sdfwb::algebra
