// Budgets: a computation that runs out of time, memory or is cancelled stops
// at a safe point with a clear "gave up after ..." result.

#include "algebra/groebner.h"
#include "algebra/ideal_operations.h"
#include "algebra/implicitization.h"
#include "example_systems.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace sdfwb::algebra {
namespace {

// Far too big to finish within any of the limits below.
Ideal hard_system() { return testing::cyclic(8); }

TEST(Budget, TimeLimit) {
  for (GroebnerMethod method : {GroebnerMethod::modular, GroebnerMethod::rational}) {
    GroebnerOptions options;
    options.method = method;
    options.budget.time_limit_seconds = 0.2;
    GroebnerResult r = groebner_basis(hard_system(), options);
    EXPECT_EQ(r.status, Status::time_limit);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.basis.empty());
    EXPECT_EQ(r.message.rfind("gave up after ", 0), 0u) << r.message;
    EXPECT_NE(r.message.find("time limit"), std::string::npos) << r.message;
  }
}

TEST(Budget, MemoryLimit) {
  GroebnerOptions options;
  options.budget.memory_limit_bytes = 256 * 1024;
  options.budget.time_limit_seconds = 30;  // a safety net; the memory limit must trigger first
  GroebnerResult r = groebner_basis(hard_system(), options);
  EXPECT_EQ(r.status, Status::memory_limit) << r.message;
  EXPECT_NE(r.message.find("memory limit"), std::string::npos) << r.message;
}

TEST(Budget, CancelledBeforeStart) {
  auto token = std::make_shared<CancelToken>();
  token->cancel();
  GroebnerOptions options;
  options.budget.cancel = token;
  GroebnerResult r = groebner_basis(testing::katsura(3), options);
  EXPECT_EQ(r.status, Status::cancelled);
  EXPECT_EQ(r.message.rfind("cancelled after ", 0), 0u) << r.message;
}

TEST(Budget, CancelledFromAnotherThread) {
  auto token = std::make_shared<CancelToken>();
  GroebnerOptions options;
  options.budget.cancel = token;
  options.budget.time_limit_seconds = 60;  // safety net only
  std::thread canceller([token] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    token->cancel();
  });
  GroebnerResult r = groebner_basis(hard_system(), options);
  canceller.join();
  EXPECT_EQ(r.status, Status::cancelled) << r.message;
}

TEST(Budget, ImplicitizationAndIdealOperationsReportGivingUp) {
  ImplicitizationOptions options;
  options.groebner.budget.time_limit_seconds = 0.005;
  // The half-angle cross-cap takes a few hundred milliseconds.
  for (const testing::NamedParametrization& example : testing::classic_parametrizations()) {
    if (example.name != "cross-cap/half-angle") continue;
    ImplicitizationResult r = implicitize(example.parametrization, options);
    EXPECT_EQ(r.status, Status::time_limit);
    EXPECT_TRUE(r.generators.empty());
    EXPECT_EQ(r.message.rfind("gave up after ", 0), 0u) << r.message;
  }
  GroebnerOptions quick;
  quick.budget.time_limit_seconds = 0.05;
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

}  // namespace
}  // namespace sdfwb::algebra
