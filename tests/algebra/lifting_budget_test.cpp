// Budgets in the lifting stage of the modular method: a cancel that arrives
// after a prime's basis is computed stops the Chinese remaindering, the
// rational reconstruction, the comparison with the next prime and the
// elimination's membership tests, instead of waiting for the next prime's
// Buchberger run (which reports its own stage, "replay").
//
// The cancel is set from the lift target's `extract`, which runs between a
// prime's Buchberger run and the lifting of its basis, so every check that
// can see it is one of the lifter's.

#include "algebra/gb_elimination.h"
#include "algebra/gb_modular.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <optional>

namespace sdfwb::algebra::gb {
namespace {

struct Outcome {
  std::optional<BudgetExceeded> exceeded;
  std::size_t bases = 0;          // prime bases handed to the lifter
  std::size_t verifications = 0;  // candidates verified
};

// Lifts the whole reduced basis of `input` and cancels when the basis modulo
// the `cancelAt`-th usable prime is handed to the lifter.
Outcome liftCancelledAt(const std::vector<Polynomial>& input, std::size_t cancelAt) {
  auto token = std::make_shared<CancelToken>();
  Budget budget;
  budget.cancel = token;
  BudgetMonitor monitor(budget);
  GroebnerStats stats;
  Outcome outcome;
  LiftTarget target;
  target.ring = input.front().ring();
  target.extract = [&](std::vector<ModPoly> basis, const ModularDomain&) {
    if (++outcome.bases == cancelAt) token->cancel();
    return basis;
  };
  target.verify = [&](const std::vector<Polynomial>&) {
    ++outcome.verifications;
    return true;
  };
  try {
    modularGroebner(input, target.ring, monitor, stats, &target);
  } catch (const BudgetExceeded& e) {
    outcome.exceeded = e;
  }
  return outcome;
}

void expectCancelledWhileLifting(const Outcome& outcome, std::size_t bases) {
  ASSERT_TRUE(outcome.exceeded.has_value()) << "the lift ran to the end";
  EXPECT_EQ(outcome.exceeded->status, Status::Cancelled);
  EXPECT_EQ(outcome.exceeded->message.rfind("cancelled after ", 0), 0u) << outcome.exceeded->message;
  EXPECT_NE(outcome.exceeded->message.find("(lifting, "), std::string::npos) << outcome.exceeded->message;
  EXPECT_EQ(outcome.bases, bases);
  EXPECT_EQ(outcome.verifications, 0u);
}

class LiftingBudget : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x"});
  Polynomial x_ = ring_->var("x");

  // The sum of c(k) x^k for k < degree, plus x^degree: a basis of one
  // element with degree + 1 terms, enough for the lifter's ticks to read
  // the clock (tick looks every 64th call).
  Polynomial dense(int degree, const std::function<Rational(int)>& c) const {
    Polynomial f = pow(x_, degree);
    for (int k = 0; k < degree; ++k) f += c(k) * pow(x_, k);
    return f;
  }
};

TEST_F(LiftingBudget, ReconstructionChecksTheBudget) {
  // Small coefficients reconstruct from the first prime alone: its lift is
  // a copy and a reconstruction of every coefficient.
  Outcome outcome = liftCancelledAt({dense(200, [](int k) -> Rational { return Rational(k % 7 + 1) / 3; })}, 1);
  expectCancelledWhileLifting(outcome, 1);
}

TEST_F(LiftingBudget, ChineseRemainderingChecksTheBudget) {
  // Coefficients of 200 bits need more than nine primes. The ninth prime's
  // basis is only combined with the others: after the eighth, the next
  // reconstruction is scheduled for the tenth (see Lifter::add).
  const Rational big(mpz_class(1) << 200);
  Outcome outcome = liftCancelledAt({dense(200, [&](int k) -> Rational { return big + k; })}, 9);
  expectCancelledWhileLifting(outcome, 9);
}

TEST_F(LiftingBudget, ComparisonWithTheNextPrimeChecksTheBudget) {
  // The first prime's candidate is right; the second prime's basis is
  // compared with it before the verification would accept it.
  Outcome outcome = liftCancelledAt({dense(3, [](int k) -> Rational { return Rational(k + 1) / 2; })}, 2);
  expectCancelledWhileLifting(outcome, 2);
}

TEST(EliminationBudget, MembershipTestsCheckTheBudget) {
  // The twisted cubic: three generators to verify by membership. The first
  // test cancels; no other may start.
  RingPtr ring = Ring::make({"t", "x", "y", "z"});
  Polynomial t = ring->var("t");
  Ideal ideal(ring, {ring->var("x") - t, ring->var("y") - pow(t, 2), ring->var("z") - pow(t, 3)});
  RingPtr remaining = Ring::make({"x", "y", "z"});
  auto token = std::make_shared<CancelToken>();
  Budget budget;
  budget.cancel = token;
  BudgetMonitor monitor(budget);
  GroebnerStats stats;
  std::size_t tests = 0;
  auto contains = [&](const Polynomial&) {
    ++tests;
    token->cancel();
    return true;
  };
  try {
    modularElimination(ideal, {"t"}, remaining, contains, monitor, stats);
    ADD_FAILURE() << "the elimination ran to the end";
  } catch (const BudgetExceeded& e) {
    EXPECT_EQ(e.status, Status::Cancelled);
    EXPECT_NE(e.message.find("(verification, "), std::string::npos) << e.message;
  }
  EXPECT_EQ(tests, 1u);
}

}  // namespace
}  // namespace sdfwb::algebra::gb
