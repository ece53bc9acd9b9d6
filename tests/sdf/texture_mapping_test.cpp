// Texture coordinates of each primitive's natural parametrization
// (texture_mapping.glsl) in the double build: where known points of each
// surface land in the image, which coordinates wrap, and that a coordinate
// runs on across the seams that wrap (u = 1 is u = 0 again).

#include <cmath>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

void expectPoint(TexturePoint t, double u, double v, const char* what) {
    EXPECT_NEAR(t.u, u, 1e-12) << what;
    EXPECT_NEAR(t.v, v, 1e-12) << what;
}

TEST(TextureMapping, SphereFrontIsTheImageCentreAndThePolesItsTopAndBottom) {
    const vec3 radii(2, 2, 2);
    expectPoint(sphericalPoint(vec3(0, 0, 2), radii), 0.5, 0.5, "front (+z)");
    expectPoint(sphericalPoint(vec3(2, 0, 0), radii), 0.75, 0.5, "a quarter turn towards +x");
    EXPECT_NEAR(sphericalPoint(vec3(0, 2, 0), radii).v, 1.0, 1e-12);
    EXPECT_NEAR(sphericalPoint(vec3(0, -2, 0), radii).v, 0.0, 1e-12);
    TexturePoint t = sphericalPoint(vec3(1, 0, 1), radii);
    EXPECT_TRUE(t.wrapU);
    EXPECT_FALSE(t.wrapV);
    // the seam at the back: either side lands at the image's two ends
    EXPECT_NEAR(sphericalPoint(vec3(-1e-9, 0, -2), radii).u, 0.0, 1e-9);
    EXPECT_NEAR(sphericalPoint(vec3(1e-9, 0, -2), radii).u, 1.0, 1e-9);
}

TEST(TextureMapping, EllipsoidMapsLikeTheSphereItIsStretchedFrom) {
    expectPoint(sphericalPoint(vec3(0, 0, 3), vec3(1, 2, 3)), 0.5, 0.5, "front");
    expectPoint(sphericalPoint(vec3(0, 2, 0), vec3(1, 2, 3)), 0.5, 1.0, "top");
}

TEST(TextureMapping, EachBoxFaceShowsTheWholeImageUprightFromOutside) {
    const vec3 h(1, 2, 3);
    expectPoint(boxFacePoint(vec3(0, 0, 3), h), 0.5, 0.5, "+z centre");
    expectPoint(boxFacePoint(vec3(-0.5, -1, 3), h), 0.25, 0.25, "+z towards the bottom left");
    expectPoint(boxFacePoint(vec3(0.5, 1, 3), h), 0.75, 0.75, "+z towards the top right");
    expectPoint(boxFacePoint(vec3(1, -2, 3), h), 0.0, 0.0, "+x: its left edge meets +z");
    expectPoint(boxFacePoint(vec3(1, 2, -3), h), 1.0, 1.0, "+x top right, seen from +x");
    expectPoint(boxFacePoint(vec3(-1, 0, 0), h), 0.5, 0.5, "-x centre");
    expectPoint(boxFacePoint(vec3(-1, 0, 3), h), 1.0, 0.5, "-x: its right edge meets +z");
    expectPoint(boxFacePoint(vec3(0, 2, -3), h), 0.5, 1.0, "+y: -z is its top edge");
    expectPoint(boxFacePoint(vec3(0.5, 0, -3), h), 0.25, 0.5, "-z seen from behind: +x is to the left");
    EXPECT_FALSE(boxFacePoint(vec3(0, 0, 3), h).wrapU);
}

TEST(TextureMapping, PlaneTilesRunAlongTheWallAndUpIt) {
    // a wall facing +z: u along +x, v up
    expectPoint(planePoint(vec3(0.5, 0.25, 0), vec3(0, 0, 1), 2.0), 1.0, 0.5, "wall");
    // a floor: u along +x, v away from a viewer at +z (towards -z)
    expectPoint(planePoint(vec3(0.5, 0, -0.25), vec3(0, 1, 0), 2.0), 1.0, 0.5, "floor");
    TexturePoint t = planePoint(vec3(0, 0, 0), vec3(0, 1, 0), 1.0);
    EXPECT_TRUE(t.wrapU && t.wrapV);
}

TEST(TextureMapping, CylinderSideGoesOnceRoundAndOnceUpAndItsCapsAreDiscs) {
    expectPoint(cylinderPoint(vec3(0, -1, 0.5), 0.5, 1), 0.5, 0.0, "front, bottom edge of the side");
    expectPoint(cylinderPoint(vec3(0.5, 1, 0), 0.5, 1), 0.75, 1.0, "+x, top edge of the side");
    expectPoint(cylinderPoint(vec3(0, 1, 0), 0.5, 1), 0.5, 0.5, "top cap centre");
    expectPoint(cylinderPoint(vec3(0.3, 1, 0.1), 0.4, 1), 0.5 + 0.3 / 0.8, 0.5 - 0.1 / 0.8, "top cap, towards +x +z");
    EXPECT_FALSE(cylinderPoint(vec3(0, 1, 0), 0.5, 1).wrapU);
}

TEST(TextureMapping, ConeSideRunsFromItsBaseToItsApex) {
    const double s = std::sin(M_PI / 3), c = std::cos(M_PI / 3), h = 1.5;
    const double base = h * c / s;
    expectPoint(conePoint(vec3(0, -h, base), s, c, h), 0.5, 0.0, "front of the base rim");
    EXPECT_NEAR(conePoint(vec3(0, -0.75, base / 2), s, c, h).v, 0.5, 1e-12);
    expectPoint(conePoint(vec3(0, -h - 0.01, 0), s, c, h), 0.5, 0.5, "base centre");
}

TEST(TextureMapping, TorusGoesRoundTheAxisAndRoundTheTube) {
    expectPoint(torusPoint(vec3(0, 0, 1.25), 1), 0.5, 0.5, "outer equator, front");
    expectPoint(torusPoint(vec3(0, 0.25, 1), 1), 0.5, 0.75, "top of the tube");
    EXPECT_NEAR(std::abs(torusPoint(vec3(0, 0, 0.75), 1).v - 0.5), 0.5, 1e-12);  // the inner equator: the seam
    TexturePoint t = torusPoint(vec3(0, 0, 1.25), 1);
    EXPECT_TRUE(t.wrapU && t.wrapV);
}

TEST(TextureMapping, CapsuleRunsFromACapToBCapRoundItsAxis) {
    const vec3 a(0, -1, 0), b(0, 1, 0);
    EXPECT_NEAR(capsulePoint(vec3(0, -1.5, 0), a, b, 0.5).v, 0.0, 1e-12);  // a's pole (u: any)
    EXPECT_NEAR(capsulePoint(vec3(0, 1.5, 0), a, b, 0.5).v, 1.0, 1e-12);   // b's pole
    expectPoint(capsulePoint(vec3(0, 0, 0.5), a, b, 0.5), 0.5, 0.5, "front, halfway");
    // along y the capsule's turn is the cylinder's
    EXPECT_NEAR(capsulePoint(vec3(0.5, 0, 0), a, b, 0.5).u, cylinderPoint(vec3(0.5, 0, 0), 0.5, 1).u, 1e-12);
}

TEST(TextureMapping, EveryMappingCodeReachesItsFunction) {
    const vec3 p(0.3, 0.4, 0.5);
    EXPECT_EQ(texturePoint(MAP_SPHERICAL, p, vec4(1, 1, 1, 0), vec4(0)).u, sphericalPoint(p, vec3(1)).u);
    EXPECT_EQ(texturePoint(MAP_BOX, p, vec4(1, 1, 1, 0), vec4(0)).v, boxFacePoint(p, vec3(1)).v);
    EXPECT_EQ(texturePoint(MAP_PLANE, p, vec4(0, 1, 0, 2), vec4(0)).u, planePoint(p, vec3(0, 1, 0), 2).u);
    EXPECT_EQ(texturePoint(MAP_CYLINDER, p, vec4(1, 1, 0, 0), vec4(0)).v, cylinderPoint(p, 1, 1).v);
    EXPECT_EQ(texturePoint(MAP_CONE, p, vec4(0.5, 0.8, 1, 0), vec4(0)).v, conePoint(p, 0.5, 0.8, 1).v);
    EXPECT_EQ(texturePoint(MAP_TORUS, p, vec4(1, 0.2, 0, 0), vec4(0)).v, torusPoint(p, 1).v);
    EXPECT_EQ(texturePoint(MAP_CAPSULE, p, vec4(0, 0, 0, 0.2), vec4(0, 1, 0, 0)).v,
              capsulePoint(p, vec3(0), vec3(0, 1, 0), 0.2).v);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
