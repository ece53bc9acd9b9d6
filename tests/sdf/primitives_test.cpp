// The shared primitives in the double build: distances at known points, the
// Lipschitz constant of every primitive, |grad| = 1 near exact surfaces.

#include <functional>
#include <ostream>
#include <random>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

using Field = std::function<double(vec3)>;

struct PrimitiveCase {
    const char* name;
    Field field;
    bool exact;                // the docs' label: exact distance, or a bound
    double extent;             // sampling box half-size
};

std::vector<PrimitiveCase> primitives() {
    return {
        {"sphere", [](vec3 p) { return sdSphere(p, 1.2); }, true, 3},
        {"box", [](vec3 p) { return sdBox(p, vec3(1, 0.5, 0.75)); }, true, 3},
        {"round_box", [](vec3 p) { return sdRoundBox(p, vec3(1, 0.5, 0.75), 0.2); }, true, 3},
        {"plane", [](vec3 p) { return sdPlane(p, normalize3(vec3(1, 2, -0.5)), 0.3); }, true, 3},
        {"torus", [](vec3 p) { return sdTorus(p, 1.0, 0.3); }, true, 3},
        {"cone", [](vec3 p) { return sdCone(p, vec2(std::sin(0.5), std::cos(0.5)), 1.5); }, false, 3},
        {"ellipsoid", [](vec3 p) { return sdEllipsoid(p, vec3(1.5, 0.7, 1.0)); }, false, 3},
        {"cylinder", [](vec3 p) { return sdCylinder(p, 0.6, 1.1); }, true, 3},
        {"capsule", [](vec3 p) { return sdCapsule(p, vec3(-0.5, -0.3, 0.1), vec3(0.7, 0.8, -0.2), 0.35); }, true, 3},
    };
}

// gtest prints parameters into CTest's test names; the name is enough.
void PrintTo(const PrimitiveCase& c, std::ostream* out) { *out << c.name; }

std::vector<PrimitiveCase> exactPrimitives() {
    std::vector<PrimitiveCase> exact;
    for (const PrimitiveCase& c : primitives()) {
        if (c.exact) exact.push_back(c);
    }
    return exact;
}

class Primitive : public ::testing::TestWithParam<PrimitiveCase> {};
class ExactPrimitive : public ::testing::TestWithParam<PrimitiveCase> {};

TEST_P(Primitive, LipschitzConstantAtMostOne) {
    const PrimitiveCase& c = GetParam();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-c.extent, c.extent), step(-0.05, 0.05);
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        vec3 p(coordinate(random), coordinate(random), coordinate(random));
        vec3 q = p + vec3(step(random), step(random), step(random));
        double separation = length3(q - p);
        if (separation < 1e-9) continue;
        worst = std::max(worst, std::abs(c.field(p) - c.field(q)) / separation);
    }
    EXPECT_LE(worst, 1.0 + 1e-5) << c.name;
}

TEST_P(ExactPrimitive, UnitGradientNearTheSurface) {
    const PrimitiveCase& c = GetParam();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-c.extent, c.extent);
    int checked = 0;
    const double h = 1e-6;
    for (int i = 0; i < 200000 && checked < 500; ++i) {
        vec3 p(coordinate(random), coordinate(random), coordinate(random));
        double d = c.field(p);
        if (std::abs(d) > 0.05) continue;
        vec3 gradient((c.field(p + vec3(h, 0, 0)) - c.field(p - vec3(h, 0, 0))) / (2 * h),
                      (c.field(p + vec3(0, h, 0)) - c.field(p - vec3(0, h, 0))) / (2 * h),
                      (c.field(p + vec3(0, 0, h)) - c.field(p - vec3(0, 0, h))) / (2 * h));
        // skip points on the medial axis (corners, edges) where the gradient jumps
        if (std::abs(length3(gradient) - 1.0) > 1e-3 && std::abs(length3(gradient) - 1.0) < 0.5) {
            ADD_FAILURE() << c.name << " |grad| = " << length3(gradient) << " at distance " << d;
        }
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

INSTANTIATE_TEST_SUITE_P(All, Primitive, ::testing::ValuesIn(primitives()),
                         [](const ::testing::TestParamInfo<PrimitiveCase>& info) { return info.param.name; });
INSTANTIATE_TEST_SUITE_P(All, ExactPrimitive, ::testing::ValuesIn(exactPrimitives()),
                         [](const ::testing::TestParamInfo<PrimitiveCase>& info) { return info.param.name; });

TEST(PrimitiveDistances, KnownPoints) {
    EXPECT_DOUBLE_EQ(sdSphere(vec3(3, 4, 0), 1), 4);
    EXPECT_DOUBLE_EQ(sdSphere(vec3(0, 0, 0), 2), -2);
    EXPECT_DOUBLE_EQ(sdBox(vec3(3, 0, 0), vec3(1, 1, 1)), 2);
    EXPECT_DOUBLE_EQ(sdBox(vec3(2, 2, 1), vec3(1, 1, 1)), std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(sdBox(vec3(0.5, 0, 0), vec3(1, 1, 1)), -0.5);
    EXPECT_NEAR(sdRoundBox(vec3(2, 2, 0), vec3(1, 1, 1), 0.25), std::sqrt(2.0) * 1.25 - 0.25, 1e-12);
    EXPECT_DOUBLE_EQ(sdPlane(vec3(0, 5, 0), vec3(0, 1, 0), 2), 3);
    EXPECT_DOUBLE_EQ(sdTorus(vec3(1, 0, 0), 1, 0.25), -0.25);
    EXPECT_DOUBLE_EQ(sdTorus(vec3(0, 3, 0), 0, 1), 2);
    EXPECT_NEAR(sdTorus(vec3(0, 0, 3), 1, 0.25), 1.75, 1e-12);
    EXPECT_DOUBLE_EQ(sdCylinder(vec3(0, 3, 0), 1, 1), 2);
    EXPECT_DOUBLE_EQ(sdCylinder(vec3(3, 0, 0), 1, 1), 2);
    EXPECT_NEAR(sdCylinder(vec3(2, 2, 0), 1, 1), std::sqrt(2.0), 1e-12);
    EXPECT_DOUBLE_EQ(sdCapsule(vec3(0, 0, 2), vec3(0, -1, 0), vec3(0, 1, 0), 0.5), 1.5);
    EXPECT_DOUBLE_EQ(sdCapsule(vec3(0, 3, 0), vec3(0, -1, 0), vec3(0, 1, 0), 0.5), 1.5);
    EXPECT_DOUBLE_EQ(sdCapsule(vec3(0, 3, 0), vec3(0, 1, 0), vec3(0, 1, 0), 0.5), 1.5);  // degenerate segment
}

TEST(PrimitiveDistances, BoundsVanishOnTheSurfaceAndKeepTheSign) {
    vec3 radii(1.5, 0.7, 1.0);
    EXPECT_NEAR(sdEllipsoid(vec3(1.5, 0, 0), radii), 0, 1e-12);
    EXPECT_NEAR(sdEllipsoid(vec3(0, 0.7, 0), radii), 0, 1e-12);
    EXPECT_LT(sdEllipsoid(vec3(0, 0, 0), radii), 0);
    EXPECT_GT(sdEllipsoid(vec3(0, 0, 3), radii), 0);
    EXPECT_LE(sdEllipsoid(vec3(0, 0, 3), radii), 2.0 + 1e-12);  // true distance is 2
    vec2 sinCos(std::sin(0.5), std::cos(0.5));
    double h = 1.5, r = h * std::tan(0.5);
    EXPECT_NEAR(sdCone(vec3(0, 0, 0), sinCos, h), 0, 1e-12);          // apex
    EXPECT_NEAR(sdCone(vec3(r, -h, 0), sinCos, h), 0, 1e-12);         // base rim
    EXPECT_LT(sdCone(vec3(0, -0.5 * h, 0), sinCos, h), 0);
    EXPECT_LE(sdCone(vec3(0, 2, 0), sinCos, h), 2.0 + 1e-12);         // true distance to the apex is 2
}

TEST(SharedMath, GuardsWhereGlslIsUndefined) {
    EXPECT_EQ(normalize3(vec3(0)), vec3(0, 0, 1));
    EXPECT_EQ(safePow(-2.0, 3.0), 0.0);
    EXPECT_EQ(safeSqrt(-1.0), 0.0);
    EXPECT_EQ(modr(5.0, 0.0), 5.0);
    EXPECT_DOUBLE_EQ(modr(-1.0, 3.0), 2.0);
    EXPECT_EQ(roundHalfUp(-0.5), 0.0);
    EXPECT_EQ(roundHalfUp(0.5), 1.0);
    EXPECT_EQ(roundHalfUp(-1.5), -1.0);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
