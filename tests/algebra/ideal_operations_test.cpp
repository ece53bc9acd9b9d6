#include "algebra/ideal_operations.h"
#include "algebra/polynomial_gcd.h"

#include <gtest/gtest.h>

#include "example_systems.h"

namespace sdfwb::algebra {
namespace {

using testing::strings;

class IdealOperations : public ::testing::Test {
 protected:
  RingPtr ring_ = Ring::make({"x", "y", "z"});
  Polynomial x_ = ring_->var("x"), y_ = ring_->var("y"), z_ = ring_->var("z");
};

TEST_F(IdealOperations, Membership) {
  Ideal i(ring_, {x_ - pow(z_, 2), y_ - pow(z_, 3)});
  Decision in = contains(i, pow(x_, 3) - pow(y_, 2));
  ASSERT_TRUE(in.ok());
  EXPECT_TRUE(in.value);
  EXPECT_FALSE(contains(i, x_ - y_).value);
}

TEST_F(IdealOperations, RadicalMembership) {
  Ideal i(ring_, {pow(x_, 3), pow(y_, 2) - z_});
  EXPECT_FALSE(contains(i, x_).value);
  Decision radical = radicalContains(i, x_);
  ASSERT_TRUE(radical.ok());
  EXPECT_TRUE(radical.value);
  EXPECT_FALSE(radicalContains(i, y_).value);
  EXPECT_TRUE(radicalContains(i, x_ * y_ + pow(y_, 2) - z_).value);
}

TEST_F(IdealOperations, SumAndProduct) {
  Ideal a(ring_, {x_, y_});
  Ideal b(ring_, {z_});
  EXPECT_EQ(strings(groebnerBasis(sum(a, b)).basis), (std::vector<std::string>{"z", "y", "x"}));
  EXPECT_EQ(strings(groebnerBasis(product(a, b)).basis), (std::vector<std::string>{"y*z", "x*z"}));
}

TEST_F(IdealOperations, Intersection) {
  GroebnerResult r = intersection(Ideal(ring_, {x_}), Ideal(ring_, {y_}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(strings(r.basis), (std::vector<std::string>{"x*y"}));
  // CLO 4.3 Example: <x^2 y> ∩ <x y^2> = <x^2 y^2>.
  EXPECT_EQ(strings(intersection(Ideal(ring_, {pow(x_, 2) * y_}), Ideal(ring_, {x_ * pow(y_, 2)})).basis),
            (std::vector<std::string>{"x^2*y^2"}));
  // <x, y> ∩ <x, z> = <x, y*z>.
  EXPECT_EQ(strings(intersection(Ideal(ring_, {x_, y_}), Ideal(ring_, {x_, z_})).basis),
            (std::vector<std::string>{"x", "y*z"}));
}

TEST_F(IdealOperations, Elimination) {
  // Twisted cubic: eliminating z from <x - z^2... > leaves the plane curve.
  GroebnerResult r = eliminate(Ideal(ring_, {x_ - z_, y_ - pow(z_, 3)}), {"z"});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(strings(r.basis), (std::vector<std::string>{"x^3 - y"}));
  EXPECT_EQ(r.basis.front().ring()->variables(), (std::vector<std::string>{"x", "y"}));
  EXPECT_THROW(eliminate(Ideal(ring_, {x_}), {"w"}), std::invalid_argument);
}

TEST_F(IdealOperations, GcdAndLcm) {
  Polynomial a = pow(x_ + y_, 2) * (x_ - 1) * 3;
  Polynomial b = (x_ + y_) * pow(x_ - 1, 3) / 2;
  EXPECT_EQ(gcd(a, b), ((x_ + y_) * (x_ - 1)));
  EXPECT_EQ(lcm(a, b), (pow(x_ + y_, 2) * pow(x_ - 1, 3)));
  EXPECT_EQ(gcd(x_, ring_->constant(5)), ring_->one());
  EXPECT_EQ(gcd(pow(x_, 2) - 1, pow(x_, 2) + 2 * x_ + 1), x_ + 1);
  EXPECT_EQ(gcd(x_ * y_ + x_, y_ * z_ + z_), y_ + 1);
}

}  // namespace
}  // namespace sdfwb::algebra

namespace sdfwb::algebra {
namespace {

TEST(IdealEdgeCases, EmptyAndTrivial) {
  auto r = Ring::make({"x", "y"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y");
  EXPECT_TRUE(groebnerBasis(Ideal(r, {})).basis.empty());
  // Eliminating every variable leaves the constants: 1 for the unit ideal,
  // nothing for a proper ideal.
  GroebnerResult all = eliminate(Ideal(r, {x * y - 1, x - y}), {"x", "y"});
  ASSERT_TRUE(all.ok());
  EXPECT_TRUE(all.basis.empty());
  GroebnerResult unit = eliminate(Ideal(r, {x * y - 1, x}), {"x", "y"});
  ASSERT_EQ(unit.basis.size(), 1u);
  EXPECT_EQ(unit.basis.front().toString(), "1");
  auto one = Ring::make({"t"}, MonomialOrder::lex());
  Polynomial t = one->var("t");
  EXPECT_EQ(groebnerBasis(Ideal(one, {pow(t, 4) - 1, pow(t, 6) - 1})).basis.front(), pow(t, 2) - 1);
}

}  // namespace
}  // namespace sdfwb::algebra
