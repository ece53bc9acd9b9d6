// The shared operators in the double build: hard and smooth booleans against
// their formulas and limits, point operators against their definitions.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

const int kVariants[] = {SMOOTH_POLYNOMIAL, SMOOTH_EXPONENTIAL, SMOOTH_POWER, SMOOTH_ROOT};

std::vector<std::pair<double, double>> operandPairs() {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> value(-2, 2);
    std::vector<std::pair<double, double>> pairs = {{0.1, 0.1}, {0.3, 0.5}, {0.5, 0.3}, {1e-3, 2}, {-0.2, 0.4}};
    for (int i = 0; i < 500; ++i) pairs.emplace_back(value(random), value(random));
    return pairs;
}

TEST(HardBooleans, AreMinAndMax) {
    for (auto [a, b] : operandPairs()) {
        EXPECT_EQ(hardMin(a, b).d, std::min(a, b));
        EXPECT_EQ(hardMax(a, b).d, std::max(a, b));
        EXPECT_EQ(hardMin(a, b).w, a <= b ? 0.0 : 1.0);
    }
}

TEST(SmoothBooleans, PolynomialMatchesTheThesisFormula) {
    for (double n : {2.0, 3.0}) {
        for (double k : {0.1, 0.5, 2.0}) {
            for (auto [a, b] : operandPairs()) {
                double omega = std::pow(std::max(k - std::abs(a - b), 0.0), n) / (2 * n * std::pow(k, n - 1));
                EXPECT_NEAR(sminPolynomial(a, b, k, n).d, std::min(a, b) - omega, 1e-12);
            }
        }
    }
}

TEST(SmoothBooleans, ExponentialMatchesTheThesisFormulaWithSharpnessFourOverK) {
    for (double k : {0.25, 0.5, 2.0}) {
        double s = 4.0 / k;
        for (auto [a, b] : operandPairs()) {
            double expected = -std::log2(std::exp2(-s * a) + std::exp2(-s * b)) / s;
            EXPECT_NEAR(sminExponential(a, b, k).d, expected, 1e-9);
        }
    }
}

TEST(SmoothBooleans, ExponentialNeverOverflows) {
    Blend far = sminExponential(1e6, 2e6, 1e-6);
    EXPECT_TRUE(std::isfinite(far.d));
    EXPECT_DOUBLE_EQ(far.d, 1e6);
}

TEST(SmoothBooleans, PowerMatchesTheFormulaForPositiveOperandsAndIsHardElsewhere) {
    for (double k : {0.1, 0.25, 0.5}) {
        double s = 1.0 / k;
        for (auto [a, b] : operandPairs()) {
            if (a > 0 && b > 0) {
                double expected = std::pow(std::pow(a, s) * std::pow(b, s) / (std::pow(a, s) + std::pow(b, s)), 1 / s);
                EXPECT_NEAR(sminPower(a, b, k).d, expected, 1e-9 * std::max(1.0, expected));
            } else {
                EXPECT_EQ(sminPower(a, b, k).d, std::min(a, b));
            }
        }
    }
}

TEST(SmoothBooleans, RootMatchesTheFormulaWithCEqualKSquaredOverFour) {
    for (double k : {0.1, 0.5, 2.0}) {
        double c = k * k / 4;
        for (auto [a, b] : operandPairs()) {
            EXPECT_NEAR(sminRoot(a, b, k).d, (a + b - std::sqrt((a - b) * (a - b) + c)) / 2, 1e-12);
        }
    }
}

TEST(SmoothBooleans, EveryVariantTendsToTheHardBooleanAsKGoesToZero) {
    for (int variant : kVariants) {
        for (auto [a, b] : operandPairs()) {
            double previous = INFINITY;
            for (double k : {1e-1, 1e-3, 1e-6, 1e-9}) {
                double error = std::abs(smoothMin(variant, a, b, k, 2).d - std::min(a, b));
                EXPECT_LE(error, previous + 1e-15) << "variant " << variant;
                previous = error;
            }
            EXPECT_LE(previous, 1e-8) << "variant " << variant << " a=" << a << " b=" << b;
            EXPECT_NEAR(smoothMax(variant, a, b, 1e-9, 2).d, std::max(a, b), 1e-8);
        }
    }
}

TEST(SmoothBooleans, AtEqualOperandsTheBlendIsAboutAQuarterOfK) {
    // the common meaning of k across variants (power is relative; see docs)
    const double k = 0.4, d = 1.0;
    EXPECT_NEAR(d - sminPolynomial(d, d, k, 2).d, k / 4, 1e-12);
    EXPECT_NEAR(d - sminExponential(d, d, k).d, k / 4, 1e-12);
    EXPECT_NEAR(d - sminRoot(d, d, k).d, k / 4, 1e-12);
}

TEST(SmoothBooleans, WeightIsTheDerivativeWithRespectToTheSecondOperand) {
    const double h = 1e-7;
    for (int variant : kVariants) {
        for (auto [a, b] : operandPairs()) {
            if (variant == SMOOTH_POWER && (a <= 0.01 || b <= 0.01)) continue;
            Blend blend = smoothMin(variant, a, b, 0.5, 2);
            double derivative = (smoothMin(variant, a, b + h, 0.5, 2).d - smoothMin(variant, a, b - h, 0.5, 2).d) / (2 * h);
            EXPECT_GE(blend.w, 0.0);
            EXPECT_LE(blend.w, 1.0);
            if (std::abs(a - b) > 1e-3) {
                EXPECT_NEAR(blend.w, derivative, 1e-5) << "variant " << variant << " a=" << a << " b=" << b;
            }
        }
    }
}

// The float build against the double build on the same (float) operands,
// magnitudes 1e-6 to 1e10 of both signs: no form may cancel when one operand is
// huge (an empty group's 1e10, a far child, the ground far below). The error
// allowed is a few float ulps of the result, the smaller operand and k.
TEST(SmoothBooleans, FloatMatchesDoubleForOperandsFrom1eMinus6To1e10) {
    const double magnitudes[] = {1e-6, 1e-3, 0.05, 0.5, 1, 3, 1e3, 1e6, 1e10};
    std::vector<float> operands;
    for (double m : magnitudes) {
        operands.push_back(static_cast<float>(m));
        operands.push_back(static_cast<float>(-m));
    }
    for (int variant : kVariants) {
        for (float k : {1e-3f, 0.1f, 0.5f, 2.0f}) {
            for (float n : {2.0f, 3.0f}) {
                for (float a : operands) {
                    for (float b : operands) {
                        f32::Blend single = f32::smoothMin(variant, a, b, k, n);
                        f32::Blend singleMax = f32::smoothMax(variant, a, b, k, n);
                        Blend exact = smoothMin(variant, a, b, k, n);
                        Blend exactMax = smoothMax(variant, a, b, k, n);
                        const double scale = std::min(std::abs(a), std::abs(b)) + k;
                        EXPECT_NEAR(single.d, exact.d, 1e-6 * (std::abs(exact.d) + scale))
                            << "variant " << variant << " k=" << k << " a=" << a << " b=" << b;
                        EXPECT_NEAR(singleMax.d, exactMax.d, 1e-6 * (std::abs(exactMax.d) + scale))
                            << "max, variant " << variant << " k=" << k << " a=" << a << " b=" << b;
                        // (the power variant's weight raises d / b to the power 1 + 1/k: 3e-5 off at k = 1e-3)
                        EXPECT_NEAR(single.w, exact.w, 1e-4) << "variant " << variant << " a=" << a << " b=" << b;
                    }
                }
            }
        }
    }
}

TEST(SmoothBooleans, MaxIsMinusMinOfNegatives) {
    for (int variant : kVariants) {
        for (auto [a, b] : operandPairs()) {
            EXPECT_EQ(smoothMax(variant, a, b, 0.3, 3).d, -smoothMin(variant, -a, -b, 0.3, 3).d);
        }
    }
}

TEST(PointOperators, RigidMotionsPreserveDistances) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> value(-3, 3);
    double angle = 0.7;
    vec3 row0(std::cos(angle), 0, -std::sin(angle)), row1(0, 1, 0), row2(std::sin(angle), 0, std::cos(angle));
    for (int i = 0; i < 200; ++i) {
        vec3 p(value(random), value(random), value(random)), q(value(random), value(random), value(random));
        EXPECT_NEAR(length3(opTranslate(p, vec3(1, 2, 3)) - opTranslate(q, vec3(1, 2, 3))), length3(p - q), 1e-12);
        EXPECT_NEAR(length3(opRotate(p, row0, row1, row2) - opRotate(q, row0, row1, row2)), length3(p - q), 1e-12);
        EXPECT_NEAR(length3(opTwist(p, 0.0) - p), 0.0, 1e-15);
        EXPECT_NEAR(length3(opTwist(p, 0.8)), length3(p), 1e-12);  // a rotation at every height
        EXPECT_NEAR(length3(opBend(p, 0.8)), length3(p), 1e-12);
    }
}

TEST(PointOperators, ScaleDividesThePoint) {
    EXPECT_EQ(opScale(vec3(2, 4, -6), 2.0), vec3(1, 2, -3));
}

TEST(PointOperators, ElongateClampsIntoTheSlab) {
    EXPECT_EQ(opElongate(vec3(0.3, 2, -3), vec3(1, 0.5, 1)), vec3(0, 1.5, -2));
}

TEST(PointOperators, MirrorTakesAbsoluteValuesOfChosenAxes) {
    EXPECT_EQ(opMirror(vec3(-1, -2, -3), vec3(1, 0, 1)), vec3(1, -2, 3));
    EXPECT_EQ(opMirror(vec3(-1, -2, -3), vec3(0, 0, 0)), vec3(-1, -2, -3));
}

TEST(PointOperators, RepeatMapsIntoClampedCellsWithHalvesRoundedUp) {
    vec3 spacing(2, 0, 3), counts(1, 0, 2);
    vec3 p(0.4, 5, -0.2);
    for (int i = -1; i <= 1; ++i) {
        for (int j = -2; j <= 2; ++j) {
            vec3 copy = p + vec3(2.0 * i, 0, 3.0 * j);
            EXPECT_NEAR(length3(opRepeat(copy, spacing, counts) - p), 0.0, 1e-12);
        }
    }
    // beyond the last copy the point keeps its offset from the outermost cell
    EXPECT_NEAR(opRepeat(vec3(7, 0, 0), spacing, counts).x, 5.0, 1e-12);
    // x/s = 0.5 exactly: floor(0.5 + 0.5) = 1 picks the upper cell
    EXPECT_EQ(opRepeat(vec3(1, 0, 0), spacing, counts).x, -1.0);
    EXPECT_EQ(opRepeat(vec3(-1, 0, 0), spacing, counts).x, -1.0);
}

TEST(PointOperators, InfiniteRepetitionIsPeriodic) {
    vec3 period(2, 0, 0.5);
    vec3 p(0.3, 7, -0.1);
    for (int i = -50; i <= 50; i += 7) {
        vec3 copy = p + vec3(2.0 * i, 0, 0.5 * i);
        EXPECT_NEAR(length3(opRepeatInfinite(copy, period) - p), 0.0, 1e-9);
    }
}

}  // namespace
}  // namespace sdfwb::sdf::f64
