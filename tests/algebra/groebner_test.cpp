#include "algebra/groebner.h"

#include <gtest/gtest.h>

#include "example_systems.h"

namespace sdfwb::algebra {
namespace {

using testing::strings;

TEST(Groebner, CoxLittleOSheaGrlex) {
  // CLO 2.7 Example 1: <x^3 - 2xy, x^2 y - 2y^2 + x> in grlex with x > y.
  auto r = Ring::make({"x", "y"}, MonomialOrder::deglex());
  Polynomial x = r->var("x"), y = r->var("y");
  GroebnerResult g = groebnerBasis(Ideal(r, {pow(x, 3) - 2 * x * y, pow(x, 2) * y - 2 * pow(y, 2) + x}));
  ASSERT_TRUE(g.ok()) << g.message;
  EXPECT_EQ(strings(g.basis), (std::vector<std::string>{"y^2 - 1/2*x", "x*y", "x^2"}));
  EXPECT_TRUE(isReducedGroebnerBasis(g.basis));
}

TEST(Groebner, TwistedCubicLex) {
  auto r = Ring::make({"t", "x", "y", "z"}, MonomialOrder::lex());
  Polynomial t = r->var("t"), x = r->var("x"), y = r->var("y"), z = r->var("z");
  GroebnerResult g = groebnerBasis(Ideal(r, {x - t, y - pow(t, 2), z - pow(t, 3)}));
  ASSERT_TRUE(g.ok()) << g.message;
  EXPECT_EQ(strings(g.basis),
            (std::vector<std::string>{"y^3 - z^2", "x*z - y^2", "x*y - z", "x^2 - y", "t - x"}));
}

TEST(Groebner, UnitIdealAndZero) {
  auto r = Ring::make({"x", "y"});
  Polynomial x = r->var("x"), y = r->var("y");
  GroebnerResult g = groebnerBasis(Ideal(r, {x * y - 1, x}));
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(strings(g.basis), (std::vector<std::string>{"1"}));
  EXPECT_TRUE(groebnerBasis(Ideal(r, {r->zero()})).basis.empty());
}

TEST(Groebner, NormalFormIsExact) {
  auto r = Ring::make({"x", "y"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y");
  GroebnerResult g = groebnerBasis(Ideal(r, {3 * x - 2 * y}));
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(normalForm(x * x + 1, g.basis).toString(), "4/9*y^2 + 1");
}

}  // namespace
}  // namespace sdfwb::algebra

namespace sdfwb::algebra {
namespace {

TEST(Groebner, LexByFglmMatchesDirectLex) {
  // Zero-dimensional lex goes through degrevlex + FGLM; the rational method
  // computes lex directly. Both must give the same reduced basis.
  auto r = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y"), z = r->var("z");
  Ideal i(r, {pow(x, 2) + pow(y, 2) + pow(z, 2) - 1, x - y + Rational(1, 3) * z, pow(y, 2) - z});
  GroebnerResult fast = groebnerBasis(i);
  ASSERT_TRUE(fast.ok());
  EXPECT_EQ(fast.method, "modular+fglm");
  GroebnerOptions rational;
  rational.method = GroebnerMethod::Rational;
  EXPECT_EQ(fast.basis, groebnerBasis(i, rational).basis);
  EXPECT_TRUE(isReducedGroebnerBasis(fast.basis));
}

TEST(Groebner, ChangeOrder) {
  auto drl = Ring::make({"x", "y"});
  Polynomial x = drl->var("x"), y = drl->var("y");
  GroebnerResult start = groebnerBasis(Ideal(drl, {pow(x, 2) - y, pow(y, 2) - x + 1}));
  ASSERT_TRUE(start.ok());
  RingPtr lex = drl->withOrder(MonomialOrder::lex());
  GroebnerResult converted = changeOrder(start.basis, lex);
  ASSERT_TRUE(converted.ok());
  std::vector<std::string> text;
  for (const Polynomial& g : converted.basis) text.push_back(g.toString());
  EXPECT_EQ(text, (std::vector<std::string>{"y^4 + 2*y^2 - y + 1", "x - y^2 - 1"}));
  // A curve is not zero-dimensional.
  GroebnerResult curve = groebnerBasis(Ideal(drl, {pow(x, 2) - y}));
  EXPECT_THROW(changeOrder(curve.basis, lex), std::invalid_argument);
}

}  // namespace
}  // namespace sdfwb::algebra

namespace sdfwb::algebra {
namespace {

TEST(Groebner, LexOfUnitAndPositiveDimensionalIdeals) {
  auto r = Ring::make({"x", "y", "z"}, MonomialOrder::lex());
  Polynomial x = r->var("x"), y = r->var("y"), z = r->var("z");
  GroebnerResult unit = groebnerBasis(Ideal(r, {x * y - 1, x}));
  ASSERT_TRUE(unit.ok());
  EXPECT_EQ(unit.basis, std::vector<Polynomial>{r->one()});
  // A curve: not zero-dimensional, so lex goes through homogenization.
  GroebnerResult curve = groebnerBasis(Ideal(r, {x - pow(z, 2), y - pow(z, 3)}));
  ASSERT_TRUE(curve.ok());
  EXPECT_EQ(curve.method, "modular+homogenized");
  GroebnerOptions rational;
  rational.method = GroebnerMethod::Rational;
  EXPECT_EQ(curve.basis, groebnerBasis(Ideal(r, {x - pow(z, 2), y - pow(z, 3)}), rational).basis);
}

}  // namespace
}  // namespace sdfwb::algebra
