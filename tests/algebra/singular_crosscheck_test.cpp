// Cross-checks our reduced Groebner bases against Singular's. Skips when
// Singular is missing, unless SDFWB_REQUIRE_SINGULAR=1 (set in CI).

#include "algebra/groebner.h"
#include "algebra/implicitization.h"
#include "example_systems.h"
#include "singular_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace sdfwb::algebra {
namespace {

bool singularRequired() {
  const char* value = std::getenv("SDFWB_REQUIRE_SINGULAR");
  return value && std::string(value) == "1";
}

#define SKIP_WITHOUT_SINGULAR()                                                                   \
  do {                                                                                           \
    if (!testing::singularPath()) {                                                             \
      if (singularRequired()) FAIL() << "Singular is required (SDFWB_REQUIRE_SINGULAR=1) but missing"; \
      GTEST_SKIP() << "Singular is not installed";                                               \
    }                                                                                            \
  } while (false)

TEST(SingularCrossCheck, ReducedBasesAgree) {
  SKIP_WITHOUT_SINGULAR();
  for (const testing::NamedSystem& system : testing::smallSystems()) {
    SCOPED_TRACE(system.name);
    GroebnerResult ours = groebnerBasis(system.ideal);
    ASSERT_TRUE(ours.ok()) << ours.message;
    testing::SingularResult theirs = testing::singularStd(system.ideal, 30);
    ASSERT_TRUE(theirs.ok) << theirs.error;
    ASSERT_EQ(ours.basis.size(), theirs.basis.size());
    for (std::size_t i = 0; i < ours.basis.size(); ++i) {
      EXPECT_EQ(ours.basis[i], theirs.basis[i]) << ours.basis[i] << "  vs  " << theirs.basis[i];
    }
  }
}

TEST(SingularCrossCheck, ImplicitEquationsAgree) {
  SKIP_WITHOUT_SINGULAR();
  for (const testing::NamedParametrization& example : testing::classicParametrizations()) {
    SCOPED_TRACE(example.name);
    ImplicitizationResult ours = implicitize(example.parametrization);
    ASSERT_TRUE(ours.ok()) << ours.message;
    EliminationProblem problem = implicitizationIdeal(example.parametrization);
    testing::SingularResult theirs = testing::singularEliminate(problem.ideal, problem.eliminated, ours.ring, 30);
    ASSERT_TRUE(theirs.ok) << theirs.error;
    ASSERT_EQ(ours.generators.size(), theirs.basis.size());
    for (std::size_t i = 0; i < ours.generators.size(); ++i) {
      EXPECT_EQ(ours.generators[i].monic(), theirs.basis[i]);
    }
  }
}

// The patches go through substitution and interpolation, Singular through
// its eliminate: random small inputs of every shape the new routes take.
TEST(SingularCrossCheck, PatchEquationsAgree) {
  SKIP_WITHOUT_SINGULAR();
  std::vector<testing::NamedParametrization> examples = testing::patchParametrizations(4);
  for (unsigned seed = 100; seed < 104; ++seed) {
    examples.push_back({"random bilinear " + std::to_string(seed), testing::bezierPatch(1, 1, true, seed)});
    examples.push_back({"random 2x1 " + std::to_string(seed), testing::bezierPatch(2, 1, seed % 2 == 0, seed)});
  }
  for (const testing::NamedParametrization& example : examples) {
    SCOPED_TRACE(example.name);
    ImplicitizationResult ours = implicitize(example.parametrization);
    ASSERT_TRUE(ours.ok()) << ours.message;
    EliminationProblem problem = implicitizationIdeal(example.parametrization);
    testing::SingularResult theirs = testing::singularEliminate(problem.ideal, problem.eliminated, ours.ring, 30);
    ASSERT_TRUE(theirs.ok) << theirs.error;
    ASSERT_EQ(ours.generators.size(), 1u);
    ASSERT_EQ(theirs.basis.size(), 1u);
    EXPECT_EQ(ours.generators[0].monic(), theirs.basis[0]);
  }
}

}  // namespace
}  // namespace sdfwb::algebra
