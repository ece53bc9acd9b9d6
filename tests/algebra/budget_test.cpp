// Budgets: a computation that runs out of time, memory or is cancelled stops
// at a safe point with a clear "gave up after ..." / "cancelled after ..."
// result naming the stage it was in.
//
// No assertion depends on a clock: a zero time limit is exceeded at the
// first safe point, memory is counted (deterministic in one thread), and a
// cancel is triggered from the progress callback after a counted number of
// reports (progress_interval_seconds = 0 reports at every safe point).

#include "algebra/groebner.h"
#include "algebra/ideal_operations.h"
#include "algebra/implicitization.h"
#include "example_systems.h"

#include <gtest/gtest.h>

#include <set>

namespace sdfwb::algebra {
namespace {

// Far too big to finish before any of the budgets below runs out.
Ideal hard_system() { return testing::cyclic(8); }

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A budget whose token is cancelled at the `n`th progress report in `stage`
// (any stage when empty).
Budget cancel_at_report(std::size_t n, std::string stage = {}) {
  auto token = std::make_shared<CancelToken>();
  auto seen = std::make_shared<std::size_t>(0);
  Budget budget;
  budget.cancel = token;
  budget.progress_interval_seconds = 0;
  budget.on_progress = [token, seen, n, stage](const Progress& p) {
    if ((stage.empty() || stage == p.stage) && ++*seen == n) token->cancel();
  };
  return budget;
}

RationalParametrization biquadratic() { return testing::bezier_patch(2, 2, true, 7); }

TEST(Budget, ZeroTimeLimitStopsAtTheFirstSafePoint) {
  for (GroebnerMethod method : {GroebnerMethod::modular, GroebnerMethod::rational}) {
    GroebnerOptions options;
    options.method = method;
    options.budget.time_limit_seconds = 0;
    GroebnerResult r = groebner_basis(hard_system(), options);
    EXPECT_EQ(r.status, Status::time_limit);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.basis.empty());
    EXPECT_TRUE(starts_with(r.message, "gave up after ")) << r.message;
    EXPECT_TRUE(has(r.message, "time limit")) << r.message;
  }
}

TEST(Budget, MemoryLimit) {
  GroebnerOptions options;
  options.budget.memory_limit_bytes = 256 * 1024;
  GroebnerResult r = groebner_basis(hard_system(), options);
  EXPECT_EQ(r.status, Status::memory_limit) << r.message;
  EXPECT_TRUE(has(r.message, "memory limit")) << r.message;
}

TEST(Budget, CancelledBeforeStart) {
  auto token = std::make_shared<CancelToken>();
  token->cancel();
  GroebnerOptions options;
  options.budget.cancel = token;
  GroebnerResult r = groebner_basis(testing::katsura(3), options);
  EXPECT_EQ(r.status, Status::cancelled);
  EXPECT_TRUE(starts_with(r.message, "cancelled after ")) << r.message;
}

TEST(Budget, CancelledDuringBuchberger) {
  GroebnerOptions options;
  options.budget = cancel_at_report(50);
  GroebnerResult r = groebner_basis(hard_system(), options);
  EXPECT_EQ(r.status, Status::cancelled) << r.message;
  EXPECT_TRUE(r.basis.empty());
  EXPECT_TRUE(has(r.message, "pairs left")) << r.message;
}

// Every stage of an implicitization stops on a cancel and says where.
TEST(Budget, ImplicitizationStopsInEveryStage) {
  // A cancel takes effect at the next safe point: the substitution has one,
  // so its cancel stops the interpolation's first.
  const std::pair<const char*, const char*> stages[] = {
      {"substitution", "(interpolation)"}, {"interpolation", "(interpolation)"}, {"verification", "(verification"}};
  for (const auto& [stage, where] : stages) {
    SCOPED_TRACE(stage);
    ImplicitizationOptions options;
    options.groebner.budget = cancel_at_report(1, stage);
    ImplicitizationResult r = implicitize(biquadratic(), options);
    EXPECT_EQ(r.status, Status::cancelled) << r.message;
    EXPECT_TRUE(r.generators.empty());
    EXPECT_TRUE(starts_with(r.message, "cancelled after ")) << r.message;
    EXPECT_TRUE(has(r.message, where)) << r.message;
  }
  // Elimination, for a parametrization with relations.
  for (const testing::NamedParametrization& example : testing::classic_parametrizations()) {
    if (example.name != "dupin-cyclide/cs") continue;
    ImplicitizationOptions options;
    options.groebner.budget = cancel_at_report(2, "buchberger");
    ImplicitizationResult r = implicitize(example.parametrization, options);
    EXPECT_EQ(r.status, Status::cancelled) << r.message;
    EXPECT_TRUE(has(r.message, "buchberger")) << r.message;
  }
}

TEST(Budget, InterpolationMemoryLimit) {
  ImplicitizationOptions options;
  // Degree 8 needs 165 unknowns; the degree search passes 64 KB of counted
  // matrices at degree 6.
  options.groebner.budget.memory_limit_bytes = 64 * 1024;
  ImplicitizationResult r = implicitize(biquadratic(), options);
  EXPECT_EQ(r.status, Status::memory_limit) << r.message;
  EXPECT_TRUE(starts_with(r.message, "gave up after ")) << r.message;
  EXPECT_TRUE(has(r.message, "memory limit")) << r.message;
  EXPECT_TRUE(has(r.message, "(interpolation")) << r.message;
}

TEST(Budget, ZeroTimeLimitInImplicitizationAndIdealOperations) {
  ImplicitizationOptions options;
  options.groebner.budget.time_limit_seconds = 0;
  ImplicitizationResult r = implicitize(biquadratic(), options);
  EXPECT_EQ(r.status, Status::time_limit);
  EXPECT_TRUE(r.generators.empty());
  EXPECT_TRUE(starts_with(r.message, "gave up after ")) << r.message;
  GroebnerOptions quick;
  quick.budget.time_limit_seconds = 0;
  Decision d = contains(hard_system(), hard_system().ring()->one(), quick);
  EXPECT_EQ(d.status, Status::time_limit);
  EXPECT_FALSE(d.ok());
}

TEST(Budget, ProgressReportsBasisAndPairs) {
  std::size_t reports = 0, largest_basis = 0, most_pairs = 0;
  GroebnerOptions options;
  options.budget.progress_interval_seconds = 0;
  options.budget.on_progress = [&](const Progress& p) {
    ++reports;
    largest_basis = std::max(largest_basis, p.basis_size);
    most_pairs = std::max(most_pairs, p.pairs_left);
  };
  GroebnerResult r = groebner_basis(testing::katsura(4), options);
  ASSERT_TRUE(r.ok());
  EXPECT_GT(reports, 0u);
  EXPECT_GT(largest_basis, 0u);
  EXPECT_GT(most_pairs, 0u);
}

TEST(Budget, ProgressReportsTheImplicitizationStagesAndPrimes) {
  std::set<std::string> stages;
  std::size_t most_primes = 0;
  ImplicitizationOptions options;
  options.groebner.budget.progress_interval_seconds = 0;
  options.groebner.budget.on_progress = [&](const Progress& p) {
    stages.insert(p.stage);
    most_primes = std::max(most_primes, p.primes);
  };
  ImplicitizationResult r = implicitize(biquadratic(), options);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(stages, (std::set<std::string>{"substitution", "interpolation", "verification"}));
  EXPECT_GT(most_primes, 0u);
}

}  // namespace
}  // namespace sdfwb::algebra
