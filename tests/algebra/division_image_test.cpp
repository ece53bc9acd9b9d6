// The univariate image test in front of exact division (algebra/division_image.h):
// it refutes divisions that are not exact, including the ones whose long
// division would run away, and never refutes one that is exact.

#include "algebra/division_image.h"
#include "algebra/division.h"
#include "algebra/polynomial.h"

#include <gtest/gtest.h>

#include <vector>

namespace sdfwb::algebra {
namespace {

class DivisionImage : public ::testing::Test {
protected:
    RingPtr ring = Ring::make({"x", "y", "z"});
    Polynomial x = ring->var("x"), y = ring->var("y"), z = ring->var("z");
};

TEST_F(DivisionImage, NeverRefutesAnExactDivision) {
    const std::vector<Polynomial> divisors = {
        x + y + 1, pow(x - 2 * z, 3) + y, Rational(3, 7) * x * y * z + Rational(1, 2), pow(y, 40) - 1, z * z + 1, x - 1,
    };
    const std::vector<Polynomial> quotients = {ring->one(), pow(x + y + z, 6), pow(x, 500) * y - Rational(5, 3) * z,
                                               Rational(-1, 9) * pow(z, 7)};
    for (const Polynomial& g : divisors) {
        for (const Polynomial& q : quotients) {
            EXPECT_FALSE(imageRefutesDivision(q * g, g)) << "(" << q.toString() << ") * (" << g.toString() << ")";
            EXPECT_EQ(divideExact(q * g, g), q);
        }
    }
}

TEST_F(DivisionImage, RefutesDivisionsThatAreNotExact) {
    EXPECT_TRUE(imageRefutesDivision(x * x + 1, x + 1));
    EXPECT_TRUE(imageRefutesDivision(pow(x + y + 1, 3) * z + 1, x + y + 1));
    EXPECT_TRUE(imageRefutesDivision(pow(x, 218), x + y + 1));
    EXPECT_TRUE(imageRefutesDivision(pow(x + 1, 4) * y, pow(x + 1, 5)));
}

// A fuzzed polynomial reduced a numerator of degree 21460 in x over x + y + 1:
// FLINT's exact division built quotient terms with binomial coefficients and
// ran past 120 s and 19 GB before it reached a term that does not divide.
TEST_F(DivisionImage, AHighDegreeNumeratorOverATrinomialIsRefusedAtOnce) {
    const Polynomial f = pow(x, 21460) * y * (x * 729 * z - 2) + pow(x + y + 1, 2) * 15 * pow(z, 4);
    EXPECT_TRUE(imageRefutesDivision(f, x + y + 1));
    EXPECT_FALSE(divideExact(f, x + y + 1).has_value());
}

TEST_F(DivisionImage, SaysNothingOfAConstantDivisor) {
    EXPECT_FALSE(imageRefutesDivision(x + 1, ring->constant(Rational(3))));
}

}  // namespace
}  // namespace sdfwb::algebra
