#include "algebra/ideal_operations.h"
#include "algebra/polynomial_gcd.h"

#include <gtest/gtest.h>

#include "example_systems.h"

namespace sdfwb::algebra {
namespace {

using testing::strings;

class IdealOperations : public ::testing::Test {
 protected:
  RingPtr ring = Ring::make({"x", "y", "z"});
  Polynomial x = ring->var("x"), y = ring->var("y"), z = ring->var("z");
};

TEST_F(IdealOperations, Membership) {
  Ideal i(ring, {x - pow(z, 2), y - pow(z, 3)});
  Decision in = contains(i, pow(x, 3) - pow(y, 2));
  ASSERT_TRUE(in.ok());
  EXPECT_TRUE(in.value);
  EXPECT_FALSE(contains(i, x - y).value);
}

TEST_F(IdealOperations, RadicalMembership) {
  Ideal i(ring, {pow(x, 3), pow(y, 2) - z});
  EXPECT_FALSE(contains(i, x).value);
  Decision radical = radical_contains(i, x);
  ASSERT_TRUE(radical.ok());
  EXPECT_TRUE(radical.value);
  EXPECT_FALSE(radical_contains(i, y).value);
  EXPECT_TRUE(radical_contains(i, x * y + pow(y, 2) - z).value);
}

TEST_F(IdealOperations, SumAndProduct) {
  Ideal a(ring, {x, y});
  Ideal b(ring, {z});
  EXPECT_EQ(strings(groebner_basis(sum(a, b)).basis), (std::vector<std::string>{"z", "y", "x"}));
  EXPECT_EQ(strings(groebner_basis(product(a, b)).basis), (std::vector<std::string>{"y*z", "x*z"}));
}

TEST_F(IdealOperations, Intersection) {
  GroebnerResult r = intersection(Ideal(ring, {x}), Ideal(ring, {y}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(strings(r.basis), (std::vector<std::string>{"x*y"}));
  // CLO 4.3 Example: <x^2 y> ∩ <x y^2> = <x^2 y^2>.
  EXPECT_EQ(strings(intersection(Ideal(ring, {pow(x, 2) * y}), Ideal(ring, {x * pow(y, 2)})).basis),
            (std::vector<std::string>{"x^2*y^2"}));
  // <x, y> ∩ <x, z> = <x, y*z>.
  EXPECT_EQ(strings(intersection(Ideal(ring, {x, y}), Ideal(ring, {x, z})).basis),
            (std::vector<std::string>{"x", "y*z"}));
}

TEST_F(IdealOperations, Elimination) {
  // Twisted cubic: eliminating z from <x - z^2... > leaves the plane curve.
  GroebnerResult r = eliminate(Ideal(ring, {x - z, y - pow(z, 3)}), {"z"});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(strings(r.basis), (std::vector<std::string>{"x^3 - y"}));
  EXPECT_EQ(r.basis.front().ring()->variables(), (std::vector<std::string>{"x", "y"}));
  EXPECT_THROW(eliminate(Ideal(ring, {x}), {"w"}), std::invalid_argument);
}

TEST_F(IdealOperations, GcdAndLcm) {
  Polynomial a = pow(x + y, 2) * (x - 1) * 3;
  Polynomial b = (x + y) * pow(x - 1, 3) / 2;
  EXPECT_EQ(gcd(a, b), ((x + y) * (x - 1)));
  EXPECT_EQ(lcm(a, b), (pow(x + y, 2) * pow(x - 1, 3)));
  EXPECT_EQ(gcd(x, ring->constant(5)), ring->one());
  EXPECT_EQ(gcd(pow(x, 2) - 1, pow(x, 2) + 2 * x + 1), x + 1);
  EXPECT_EQ(gcd(x * y + x, y * z + z), y + 1);
}

}  // namespace
}  // namespace sdfwb::algebra

namespace sdfwb::algebra {
namespace {

TEST(IdealEdgeCases, EmptyAndTrivial) {
  auto r = Ring::make({"x", "y"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y");
  EXPECT_TRUE(groebner_basis(Ideal(r, {})).basis.empty());
  // Eliminating every variable leaves the constants: 1 for the unit ideal,
  // nothing for a proper ideal.
  GroebnerResult all = eliminate(Ideal(r, {x * y - 1, x - y}), {"x", "y"});
  ASSERT_TRUE(all.ok());
  EXPECT_TRUE(all.basis.empty());
  GroebnerResult unit = eliminate(Ideal(r, {x * y - 1, x}), {"x", "y"});
  ASSERT_EQ(unit.basis.size(), 1u);
  EXPECT_EQ(unit.basis.front().to_string(), "1");
  auto one = Ring::make({"t"}, MonomialOrder::lex());
  Polynomial t = one->var("t");
  EXPECT_EQ(groebner_basis(Ideal(one, {pow(t, 4) - 1, pow(t, 6) - 1})).basis.front(), pow(t, 2) - 1);
}

}  // namespace
}  // namespace sdfwb::algebra
