// Budgets: a computation that runs out of time, memory or is cancelled stops
// at a safe point with a clear "gave up after ..." / "cancelled after ..."
// result naming the stage it was in.
//
// No assertion depends on a clock: a zero time limit is exceeded at the
// first safe point, memory is counted (deterministic in one thread), and a
// cancel is triggered from the progress callback after a counted number of
// reports (progressIntervalSeconds = 0 reports at every safe point).

#include "algebra/groebner.h"
#include "algebra/ideal_operations.h"
#include "algebra/implicitization.h"
#include "example_systems.h"

#include <gtest/gtest.h>

#include <set>

namespace sdfwb::algebra {
namespace {

// Far too big to finish before any of the budgets below runs out.
Ideal hardSystem() { return testing::cyclic(8); }

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A budget whose token is cancelled at the `n`th progress report in `stage`
// (any stage when empty).
Budget cancelAtReport(std::size_t n, std::string stage = {}) {
  auto token = std::make_shared<CancelToken>();
  auto seen = std::make_shared<std::size_t>(0);
  Budget budget;
  budget.cancel = token;
  budget.progressIntervalSeconds = 0;
  budget.onProgress = [token, seen, n, stage](const Progress& p) {
    if ((stage.empty() || stage == p.stage) && ++*seen == n) token->cancel();
  };
  return budget;
}

RationalParametrization biquadratic() { return testing::bezierPatch(2, 2, true, 7); }

TEST(Budget, ZeroTimeLimitStopsAtTheFirstSafePoint) {
  for (GroebnerMethod method : {GroebnerMethod::Modular, GroebnerMethod::Rational}) {
    GroebnerOptions options;
    options.method = method;
    options.budget.timeLimitSeconds = 0;
    GroebnerResult r = groebnerBasis(hardSystem(), options);
    EXPECT_EQ(r.status, Status::TimeLimit);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.basis.empty());
    EXPECT_TRUE(startsWith(r.message, "gave up after ")) << r.message;
    EXPECT_TRUE(has(r.message, "time limit")) << r.message;
  }
}

TEST(Budget, MemoryLimit) {
  GroebnerOptions options;
  options.budget.memoryLimitBytes = 256 * 1024;
  GroebnerResult r = groebnerBasis(hardSystem(), options);
  EXPECT_EQ(r.status, Status::MemoryLimit) << r.message;
  EXPECT_TRUE(has(r.message, "memory limit")) << r.message;
}

TEST(Budget, CancelledBeforeStart) {
  auto token = std::make_shared<CancelToken>();
  token->cancel();
  GroebnerOptions options;
  options.budget.cancel = token;
  GroebnerResult r = groebnerBasis(testing::katsura(3), options);
  EXPECT_EQ(r.status, Status::Cancelled);
  EXPECT_TRUE(startsWith(r.message, "cancelled after ")) << r.message;
}

TEST(Budget, CancelledDuringBuchberger) {
  GroebnerOptions options;
  options.budget = cancelAtReport(50);
  GroebnerResult r = groebnerBasis(hardSystem(), options);
  EXPECT_EQ(r.status, Status::Cancelled) << r.message;
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
    options.groebner.budget = cancelAtReport(1, stage);
    ImplicitizationResult r = implicitize(biquadratic(), options);
    EXPECT_EQ(r.status, Status::Cancelled) << r.message;
    EXPECT_TRUE(r.generators.empty());
    EXPECT_TRUE(startsWith(r.message, "cancelled after ")) << r.message;
    EXPECT_TRUE(has(r.message, where)) << r.message;
  }
  // Elimination, for a parametrization with relations.
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    if (example.name != "dupin-cyclide/cs") continue;
    ImplicitizationOptions options;
    options.groebner.budget = cancelAtReport(2, "buchberger");
    ImplicitizationResult r = implicitize(example.parametrization, options);
    EXPECT_EQ(r.status, Status::Cancelled) << r.message;
    EXPECT_TRUE(has(r.message, "buchberger")) << r.message;
  }
}

TEST(Budget, InterpolationMemoryLimit) {
  ImplicitizationOptions options;
  // Degree 8 needs 165 unknowns; the degree search passes 64 KB of counted
  // matrices at degree 6.
  options.groebner.budget.memoryLimitBytes = 64 * 1024;
  ImplicitizationResult r = implicitize(biquadratic(), options);
  EXPECT_EQ(r.status, Status::MemoryLimit) << r.message;
  EXPECT_TRUE(startsWith(r.message, "gave up after ")) << r.message;
  EXPECT_TRUE(has(r.message, "memory limit")) << r.message;
  EXPECT_TRUE(has(r.message, "(interpolation")) << r.message;
}

TEST(Budget, ZeroTimeLimitInImplicitizationAndIdealOperations) {
  ImplicitizationOptions options;
  options.groebner.budget.timeLimitSeconds = 0;
  ImplicitizationResult r = implicitize(biquadratic(), options);
  EXPECT_EQ(r.status, Status::TimeLimit);
  EXPECT_TRUE(r.generators.empty());
  EXPECT_TRUE(startsWith(r.message, "gave up after ")) << r.message;
  GroebnerOptions quick;
  quick.budget.timeLimitSeconds = 0;
  Decision d = contains(hardSystem(), hardSystem().ring()->one(), quick);
  EXPECT_EQ(d.status, Status::TimeLimit);
  EXPECT_FALSE(d.ok());
}

TEST(Budget, ProgressReportsBasisAndPairs) {
  std::size_t reports = 0, largestBasis = 0, mostPairs = 0;
  GroebnerOptions options;
  options.budget.progressIntervalSeconds = 0;
  options.budget.onProgress = [&](const Progress& p) {
    ++reports;
    largestBasis = std::max(largestBasis, p.basisSize);
    mostPairs = std::max(mostPairs, p.pairsLeft);
  };
  GroebnerResult r = groebnerBasis(testing::katsura(4), options);
  ASSERT_TRUE(r.ok());
  EXPECT_GT(reports, 0u);
  EXPECT_GT(largestBasis, 0u);
  EXPECT_GT(mostPairs, 0u);
}

TEST(Budget, ProgressReportsTheImplicitizationStagesAndPrimes) {
  std::set<std::string> stages;
  std::size_t mostPrimes = 0;
  ImplicitizationOptions options;
  options.groebner.budget.progressIntervalSeconds = 0;
  options.groebner.budget.onProgress = [&](const Progress& p) {
    stages.insert(p.stage);
    mostPrimes = std::max(mostPrimes, p.primes);
  };
  ImplicitizationResult r = implicitize(biquadratic(), options);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(stages, (std::set<std::string>{"substitution", "interpolation", "verification"}));
  EXPECT_GT(mostPrimes, 0u);
}

}  // namespace
}  // namespace sdfwb::algebra
