// The formula language's transcendental functions (sdf/glsl/transcendental.glsl)
// in the float build against the C library in double: the error they trade
// for being computed bit for bit alike on llvmpipe and in C++.

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f32 {
namespace {

// Largest |approximation - exact| / scale over samples of [lo, hi].
template <class F, class G, class S>
double worstError(F approximate, G exact, S scale, float lo, float hi) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(lo, hi);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
        float x = value(random);
        double e = exact(double(x));
        worst = std::max(worst, std::abs(double(approximate(x)) - e) / scale(e));
    }
    return worst;
}

constexpr double kUlp = std::numeric_limits<float>::epsilon();  // 2^-23, one ulp at 1

TEST(FormulaTranscendentals, SinAndCosAreWithinTwoUlpsOfOneUpTo1e4) {
    auto one = [](double) { return 1.0; };
    for (float range : {4.0f, 100.0f, 1e4f}) {
        EXPECT_LE(worstError(formulaSin, [](double x) { return std::sin(x); }, one, -range, range), 2 * kUlp) << range;
        EXPECT_LE(worstError(formulaCos, [](double x) { return std::cos(x); }, one, -range, range), 2 * kUlp) << range;
    }
    EXPECT_LE(worstError(formulaTan, [](double x) { return std::tan(x); }, [](double e) { return std::max(1.0, std::abs(e)); },
                         -1.4f, 1.4f),
              4 * kUlp);
}

TEST(FormulaTranscendentals, ExpAndLogAreWithinTwoUlps) {
    auto relative = [](double e) { return std::abs(e); };
    EXPECT_LE(worstError(formulaExp, [](double x) { return std::exp(x); }, relative, -87.0f, 88.7f), 2 * kUlp);
    EXPECT_LE(worstError(formulaLog, [](double x) { return std::log(x); }, [](double e) { return std::max(1.0, std::abs(e)); },
                         1e-30f, 1e30f),
              2 * kUlp);
    EXPECT_LE(worstError(formulaLog, [](double x) { return std::log(x); }, [](double) { return 1.0; }, 0.5f, 2.0f), 2 * kUlp);
    EXPECT_EQ(formulaExp(-100.0f), 0.0f);
    EXPECT_EQ(formulaExp(100.0f), std::numeric_limits<float>::infinity());
    EXPECT_EQ(formulaLog(0.0f), -std::numeric_limits<float>::infinity());
    EXPECT_EQ(formulaLog(std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
    EXPECT_EQ(formulaLog(1.0f), 0.0f);
    EXPECT_EQ(formulaExp(0.0f), 1.0f);
}

TEST(FormulaTranscendentals, PowIsExpOfLog) {
    EXPECT_NEAR(formulaPow(2.0f, 10.0f), 1024.0f, 1024.0f * 8 * kUlp);
    EXPECT_NEAR(formulaPow(9.0f, 0.5f), 3.0f, 3.0f * 4 * kUlp);
    EXPECT_NEAR(formulaPow(0.3f, -1.7f), std::pow(0.3, -1.7), std::pow(0.3, -1.7) * 8 * kUlp);
}

}  // namespace
}  // namespace sdfwb::sdf::f32
