// The environment map's directions (environment.glsl) in the double build and
// the float atan2 both backends share: where a direction lands on the
// latitude-longitude map, the mirror ball and the box's faces, the faces
// meeting edge to edge, and the mip layout's offsets.

#include <cmath>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

void expectPoint(MapPoint m, int face, double u, double v, const char* what) {
    EXPECT_EQ(m.face, face) << what;
    EXPECT_NEAR(m.u, u, 1e-12) << what;
    EXPECT_NEAR(m.v, v, 1e-12) << what;
}

TEST(EnvironmentDirections, EquirectCentreLooksDownMinusZAndTurnsRightToPlusX) {
    expectPoint(equirectPoint(vec3(0, 0, -1)), 0, 0.5, 0.5, "ahead");
    expectPoint(equirectPoint(vec3(1, 0, 0)), 0, 0.75, 0.5, "right");
    expectPoint(equirectPoint(vec3(-1, 0, 0)), 0, 0.25, 0.5, "left");
    expectPoint(equirectPoint(normalize3(vec3(0, 1, -1))), 0, 0.5, 0.75, "45 degrees up");
    EXPECT_NEAR(equirectPoint(vec3(0, 1, 0)).v, 1.0, 1e-12);
    EXPECT_NEAR(equirectPoint(vec3(0, -1, 0)).v, 0.0, 1e-12);
}

TEST(EnvironmentDirections, SphereMapIsTheMirrorBallSeenFromPlusZ) {
    expectPoint(spherePoint(vec3(0, 0, 1)), 0, 0.5, 0.5, "straight back at the viewer");
    // the ball's normal halves the way between +z and d: (1, 0, 1) / sqrt 2
    expectPoint(spherePoint(vec3(1, 0, 0)), 0, 0.5 + 0.5 / std::sqrt(2.0), 0.5, "right");
    expectPoint(spherePoint(vec3(0, 1, 0)), 0, 0.5, 0.5 + 0.5 / std::sqrt(2.0), "up");
    MapPoint behind = spherePoint(vec3(0, 0, -1));
    EXPECT_NEAR(std::hypot(behind.u - 0.5, behind.v - 0.5), 0.5, 1e-12);  // the rim
}

TEST(EnvironmentDirections, EachAxisLandsAtTheCentreOfItsFace) {
    const vec3 axes[] = {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1)};
    for (int face = 0; face < 6; ++face) expectPoint(boxPoint(axes[face] * 3.0), face, 0.5, 0.5, "axis");
}

// Along each edge of the cube the two faces that share it agree on the
// direction: a direction a hair either side lands on the shared edge of both.
TEST(EnvironmentDirections, BoxFacesMeetEdgeToEdgeAsAHorizontalCross) {
    const double h = 1e-9;
    // -z (front) right edge = +x left edge, at height 0.3
    MapPoint front = boxPoint(vec3(1 - h, 0.3, -1));
    MapPoint right = boxPoint(vec3(1, 0.3, -1 + h));
    EXPECT_EQ(front.face, 5);
    EXPECT_EQ(right.face, 0);
    EXPECT_NEAR(front.u, 1, 1e-6);
    EXPECT_NEAR(right.u, 0, 1e-6);
    EXPECT_NEAR(front.v, right.v, 1e-6);
    // -z top edge = +y bottom edge
    MapPoint top = boxPoint(vec3(0.4, 1, -1 + h));
    front = boxPoint(vec3(0.4, 1 - h, -1));
    EXPECT_EQ(top.face, 2);
    EXPECT_NEAR(front.v, 1, 1e-6);
    EXPECT_NEAR(top.v, 0, 1e-6);
    EXPECT_NEAR(front.u, top.u, 1e-6);
    // -z bottom edge = -y top edge
    MapPoint bottom = boxPoint(vec3(0.4, -1, -1 + h));
    front = boxPoint(vec3(0.4, -1 + h, -1));
    EXPECT_EQ(bottom.face, 3);
    EXPECT_NEAR(front.v, 0, 1e-6);
    EXPECT_NEAR(bottom.v, 1, 1e-6);
    EXPECT_NEAR(front.u, bottom.u, 1e-6);
    // +x right edge = +z left edge
    MapPoint east = boxPoint(vec3(1, -0.2, 1 - h));
    MapPoint back = boxPoint(vec3(1 - h, -0.2, 1));
    EXPECT_EQ(back.face, 4);
    EXPECT_NEAR(east.u, 1, 1e-6);
    EXPECT_NEAR(back.u, 0, 1e-6);
    EXPECT_NEAR(east.v, back.v, 1e-6);
}

TEST(EnvironmentDirections, MipLevelsFollowEachOther) {
    for (int side : {1, 2, 8, 1024}) {
        int offset = 0;
        for (int level = 0; (side >> level) >= 1; ++level) {
            EXPECT_EQ(mipLevelOffset(side, level), offset) << side << " level " << level;
            offset += (side >> level) * (side >> level);
        }
        EXPECT_EQ(mipPyramidTexels(side), offset) << side;
    }
}

TEST(EnvironmentDirections, FloatAtan2IsWithinItsBoundEverywhere) {
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        double a = -M_PI + 2 * M_PI * (i + 0.5) / 20000;
        for (double r : {1e-3, 1.0, 1e4}) {
            float y = static_cast<float>(r * std::sin(a)), x = static_cast<float>(r * std::cos(a));
            worst = std::max(worst, std::abs(double(f32::formulaAtan2(y, x)) - std::atan2(double(y), double(x))));
        }
    }
    EXPECT_LT(worst, 1e-5);
    EXPECT_EQ(f32::formulaAtan2(0.0f, 0.0f), 0.0f);
    EXPECT_NEAR(f32::formulaAtan2(0.0f, -1.0f), M_PI, 1e-6);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
