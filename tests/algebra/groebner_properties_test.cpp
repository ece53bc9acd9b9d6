// Properties every computed basis must have, checked on the shared small
// systems with both exact methods: it is a reduced Groebner basis, every
// input generator reduces to 0, and it depends neither on the order nor on
// the scaling of the generators. (The rational method is skipped for lex,
// where its intermediate coefficients swell to seconds of work.)

#include "algebra/groebner.h"
#include "example_systems.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace sdfwb::algebra {
namespace {

TEST(GroebnerProperties, OnSmallSystems) {
  for (const testing::NamedSystem& system : testing::smallSystems()) {
    SCOPED_TRACE(system.name);
    GroebnerOptions modular, rational;
    modular.method = GroebnerMethod::Modular;
    rational.method = GroebnerMethod::Rational;
    const bool tryRational = system.ideal.ring()->order().kind() != MonomialOrder::Kind::Lex;
    GroebnerResult a = groebnerBasis(system.ideal, modular);
    ASSERT_TRUE(a.ok());
    if (tryRational) {
      EXPECT_EQ(groebnerBasis(system.ideal, rational).basis, a.basis);
    }
    EXPECT_TRUE(isReducedGroebnerBasis(a.basis));
    for (const Polynomial& f : system.ideal.generators()) EXPECT_TRUE(normalForm(f, a.basis).isZero()) << f;

    std::vector<Polynomial> shuffled = system.ideal.generators();
    std::reverse(shuffled.begin(), shuffled.end());
    for (std::size_t k = 0; k < shuffled.size(); ++k) shuffled[k] *= Rational(static_cast<long>(k) + 2, 3);
    std::rotate(shuffled.begin(), shuffled.begin() + 1, shuffled.end());
    EXPECT_EQ(groebnerBasis(Ideal(system.ideal.ring(), shuffled), modular).basis, a.basis);
    if (tryRational) {
      EXPECT_EQ(groebnerBasis(Ideal(system.ideal.ring(), shuffled), rational).basis, a.basis);
    }
  }
}

TEST(GroebnerProperties, ReducedBasisCheckRejects) {
  auto r = Ring::make({"x", "y"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y");
  EXPECT_TRUE(isReducedGroebnerBasis({y - 1, x - 1}));
  EXPECT_FALSE(isReducedGroebnerBasis({x - 1, y - 1}));          // not sorted
  EXPECT_FALSE(isReducedGroebnerBasis({y - 1, 2 * x - 1}));      // not monic
  EXPECT_FALSE(isReducedGroebnerBasis({y - 1, x - y}));          // tail divisible by y
  EXPECT_FALSE(isReducedGroebnerBasis({pow(y, 2) - 1, x * y - 1}));  // S-pair does not reduce to 0
}

}  // namespace
}  // namespace sdfwb::algebra
