// The ray tree of sdf/glsl/ray_tree.glsl in the double build, against Snell's
// law and the notes' reflection formulas: the direction functions alone, and
// whole samples through the shared driver loop (sample_driver.glsl) over
// analytic fields, where a detector plane's emission reports where the last
// ray of the tree landed.

#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "sdf/shared.h"

namespace sdfwb::sdf::f64 {
namespace {

constexpr double kIor = 1.5;

TEST(RayTreeDirections, ReflectionIsTwoNDotVNMinusV) {
    vec3 n(0, 1, 0);
    vec3 d = normalize3(vec3(1, -2, 0.5));
    vec3 v = -d;
    vec3 expected = n * (2 * dot3(n, v)) - v;
    vec3 r = reflectDirection(d, n);
    EXPECT_NEAR(r.x, expected.x, 1e-15);
    EXPECT_NEAR(r.y, expected.y, 1e-15);
    EXPECT_NEAR(r.z, expected.z, 1e-15);
}

TEST(RayTreeDirections, RefractionFollowsSnellsLaw) {
    vec3 n(0, 1, 0);
    for (double degrees : {0.0, 10.0, 30.0, 60.0, 89.0}) {
        double a = degrees * M_PI / 180;
        vec3 d(std::sin(a), -std::cos(a), 0);
        Refraction t = refractDirection(d, n, 1 / kIor);
        ASSERT_FALSE(t.total);
        double sinT = std::sqrt(t.direction.x * t.direction.x + t.direction.z * t.direction.z);
        EXPECT_NEAR(1.0 * std::sin(a), kIor * sinT, 1e-12) << degrees;
        EXPECT_LT(t.direction.y, 0);  // into the solid
        EXPECT_NEAR(length3(t.direction), 1, 1e-12);
    }
}

// The notes' condition, 1 < r^2 (1 - (i.n)^2), from inside glass: beyond
// asin(1 / 1.5) = 41.81 degrees there is no refracted ray.
TEST(RayTreeDirections, TotalInternalReflectionBeyondTheCriticalAngle) {
    vec3 n(0, 1, 0);  // facing the ray, which travels inside
    double critical = std::asin(1 / kIor) * 180 / M_PI;
    for (double degrees : {critical - 0.5, critical + 0.5, 60.0, 85.0}) {
        double a = degrees * M_PI / 180;
        vec3 d(std::sin(a), -std::cos(a), 0);
        Refraction t = refractDirection(d, n, kIor);
        EXPECT_EQ(t.total, degrees > critical) << degrees;
    }
}

TEST(RayTreeDirections, SchlickShareAtNormalIncidenceIsR0) {
    Material glass = noMaterial();
    glass.ior = kIor;
    glass.fresnel = 1;
    vec3 n(0, 1, 0), d(0, -1, 0);
    Refraction t = refractDirection(d, n, 1 / kIor);
    EXPECT_NEAR(fresnelShare(glass, 1.0, t, 1 / kIor), 0.04, 1e-12);
    glass.fresnel = 0;  // the notes' model: nothing of k_t reflects
    EXPECT_EQ(fresnelShare(glass, 1.0, t, 1 / kIor), 0.0);
    Refraction total = refractDirection(normalize3(vec3(1, -0.2, 0)), n, kIor);
    EXPECT_EQ(fresnelShare(glass, 0.2, total, kIor), 1.0);
}

// One sample of the shared driver over an analytic field, no lights, no
// ambient light: a surface adds only its emission, so the sample's colour is
// the weighted emission where the rays of the tree end.
struct AnalyticDriver {
    std::vector<vec4> params;
    std::function<Sample(vec3)> field;
    std::vector<vec4> texels = {};  // an environment map's, if any
    int reads = MATERIAL_READS_SHADING;  // what the next evaluation reads (setMaterialReads)

    vec4 P(int slot) const { return params[static_cast<size_t>(slot)]; }
    // the driver's split loop: the material phase's samples taken by the outer
    // loop; the other evaluations carry a material only where their phase
    // reads one (the transparency, in shadows), as the CPU backend's do
    bool materialSampledApart() const { return true; }
    Sample mapDistance(vec3 p) const {
        Sample s = field(p);
        return reads == MATERIAL_READS_NONE ? Sample(s.d, s.step, noMaterial()) : s;
    }
    Sample mapMaterial(vec3 p) const { return field(p); }
    bool secondaryRays() const { return true; }
    bool environmentMap() const { return !texels.empty(); }
    bool imageTextures() const { return false; }
    int materialSamplesPerHit() const { return 1; }
    void setTextureStretch(real) {}
    void setFootprintShift(vec4) {}  // its fields have no patterns
    void setMaterialReads(int r) { reads = r; }
    vec4 T(int i) const { return texels.at(static_cast<size_t>(i)); }

#include "sdf/glsl/environment_lookup.glsl"
#include "sdf/glsl/mipmap_lookup.glsl"
#include "sdf/glsl/sample_driver.glsl"
};

Material glassMaterial() {
    Material m = noMaterial();
    m.transparency = 1;
    m.ior = kIor;
    return m;
}

// Emits (x, z, 1) where it is hit: the landing point and the weight that arrives.
Material detectorAt(vec3 p) {
    Material m = noMaterial();
    m.emission = vec3(p.x, p.z, 1);
    return m;
}

// The analytic traces' settings: a tight epsilon, no lights, shadows or AO
// (a test that wants them sets them).
TraceSettings analyticSettings(int maxDepth) {
    return {.maxSteps = 2000,
            .maxDistance = 100,
            .epsilon = 1e-6,
            .epsilonPerDistance = 0,
            .shadowMode = SHADOW_NONE,
            .shadowSteps = 1,
            .aoSamples = 0,
            .aoDistance = 1,
            .lightingModel = LIGHTING_BLINN_PHONG,
            .relaxation = 1,
            .lightCount = 0,
            .exposure = 1,
            .ambientLight = vec3(0),
            .background = vec3(0),
            .maxDepth = maxDepth,
            .rayWeightCutoff = 1e-3,
            .groundPlane = 0,
            .groundHeight = 0};
}

vec3 traceOne(std::function<Sample(vec3)> field, vec3 eye, vec3 direction, int maxDepth = 4) {
    AnalyticDriver driver{std::vector<vec4>(static_cast<size_t>(MATERIAL_SLOT), vec4(0)), std::move(field)};
    TraceSettings settings = analyticSettings(maxDepth);
    for (int i = 0; i < TRACE_SLOTS; ++i)
        driver.params[static_cast<size_t>(TRACE_SLOT + i)] = traceSettingsSlot(settings, i);
    vec3 forward = normalize3(direction);
    vec3 right = normalize3(cross3(forward, std::abs(forward.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    Camera camera{eye, forward, right, cross3(right, forward), 0.5};
    for (int i = 0; i < CAMERA_SLOTS; ++i) driver.params[static_cast<size_t>(CAMERA_SLOT + i)] = cameraSlot(camera, i);
    return driver.traceSample(5, 5, 10, 10).color;  // the centre of a 10 x 10 image: along `direction`
}

// A glass slab 0 <= y <= 1 over a detector plane at y = floor.
Sample slabOver(vec3 p, double floor) {
    double slab = std::abs(p.y - 0.5) - 0.5;
    double detector = p.y - floor;
    return slab < detector ? shapeSample(slab, glassMaterial()) : shapeSample(detector, detectorAt(p));
}

TEST(RayTreeSamples, ASlabShiftsARayAndItLeavesParallelToItsEntry) {
    for (double degrees : {20.0, 45.0, 70.0}) {
        double a = degrees * M_PI / 180;
        vec3 eye(0, 2, 0), d(std::sin(a), -std::cos(a), 0);
        double inside = std::asin(std::sin(a) / kIor);
        // 1 unit of air to the slab, 1 of glass, then (1 and 2) of air to the detector
        double near = traceOne([](vec3 p) { return slabOver(p, -1); }, eye, d).x;
        double far = traceOne([](vec3 p) { return slabOver(p, -2); }, eye, d).x;
        double expectedNear = std::tan(a) + std::tan(inside) + std::tan(a);
        EXPECT_NEAR(near, expectedNear, 1e-4) << degrees;
        EXPECT_NEAR(far - near, std::tan(a), 1e-4) << degrees << ": the exit ray is not parallel to the entry";
        // all of the weight arrives: k_t = 1, no Fresnel share, no reflection
        EXPECT_NEAR(traceOne([](vec3 p) { return slabOver(p, -1); }, eye, d).z, 1, 1e-12);
    }
}

// Into the top of a tall glass column, |x| <= 1: inside, the ray meets the
// wall x = 1 at 90 - theta_t >= 48.2 degrees, beyond the critical angle, and
// reflects totally with all of k_t M_T; it leaves through the bottom.
TEST(RayTreeSamples, AGlassWallBeyondTheCriticalAngleReflectsTotally) {
    auto column = [](vec3 p) {
        double box = std::max(std::abs(p.x) - 1, std::abs(p.y - 1) - 1);  // 0 <= y <= 2
        double detector = p.y + 1;
        return box < detector ? shapeSample(box, glassMaterial()) : shapeSample(detector, detectorAt(p));
    };
    double a = 60 * M_PI / 180;
    vec3 eye(0, 2.5, 0), d(std::sin(a), -std::cos(a), 0);
    double inside = std::asin(std::sin(a) / kIor);
    double entry = 0.5 * std::tan(a);                // x where the ray enters the top face, y = 2
    double toWall = (1 - entry) / std::tan(inside);  // depth below the top where it meets the wall
    ASSERT_LT(toWall, 2);
    double down = 2 - toWall;                      // depth left to the bottom after the wall
    double bottomX = 1 - down * std::tan(inside);  // mirrored by the wall
    ASSERT_GT(bottomX, -1);
    double landing = bottomX - 1 * std::tan(a);  // out parallel to the entry, mirrored, 1 unit to y = -1
    vec3 c = traceOne(column, eye, d, 6);
    EXPECT_NEAR(c.x, landing, 1e-4);
    EXPECT_NEAR(c.z, 1, 1e-12) << "total internal reflection lost weight";
}

// Past max_depth the notes' RayTracing returns black.
TEST(RayTreeSamples, RaysPastTheDepthAreBlack) {
    vec3 eye(0, 2, 0), d(0.3, -1, 0);
    // the slab's top is hit by the primary ray, its bottom by bounce 1, the detector by bounce 2
    EXPECT_NEAR(traceOne([](vec3 p) { return slabOver(p, -1); }, eye, d, 2).z, 1, 1e-12);
    EXPECT_EQ(traceOne([](vec3 p) { return slabOver(p, -1); }, eye, d, 1).z, 0);
}

// A plane of k_ps = 0.5 and colour M_PS adds that much of what it mirrors to its own light.
TEST(RayTreeSamples, AMirrorAddsKpsMpsTimesWhatItSees) {
    auto scene = [](vec3 p) {
        Material mirror = noMaterial();
        mirror.reflectivity = 0.5;
        mirror.reflectionColor = vec3(1, 0.5, 0.25);
        mirror.emission = vec3(0.1, 0.1, 0.1);
        double plane = p.y;
        double detector = 3 - p.y;  // a ceiling at y = 3, seen in the mirror
        return plane < detector ? shapeSample(plane, mirror) : shapeSample(detector, detectorAt(p));
    };
    vec3 c = traceOne(scene, vec3(0, 1, 0), vec3(1, -1, 0));
    // hits the mirror at x = 1, reflects up at 45 degrees, meets the ceiling at x = 4
    EXPECT_NEAR(c.x, 0.1 + 0.5 * 1 * 4, 1e-4);
    EXPECT_NEAR(c.y, 0.1 + 0.5 * 0.5 * 0, 1e-4);
    EXPECT_NEAR(c.z, 0.1 + 0.5 * 0.25 * 1, 1e-9);
}

// A white floor lit from straight above through a box 1 <= y <= 1.5 over the
// origin, seen from the side below the box: in every shadow mode the lit
// floor under the box shows what the box lets through, k_t M_T per channel
// (the documented simplification), or 0 when the box is opaque.
vec3 floorUnderBox(Material box, int shadowMode) {
    auto field = [box](vec3 p) {
        Material floor = noMaterial();
        floor.diffuse = vec3(1);
        double cube = std::max(std::max(std::abs(p.x), std::abs(p.z)) - 0.5, std::abs(p.y - 1.25) - 0.25);
        return cube < p.y ? shapeSample(cube, box) : shapeSample(p.y, floor);
    };
    AnalyticDriver driver{std::vector<vec4>(static_cast<size_t>(MATERIAL_SLOT), vec4(0)), field};
    TraceSettings settings = analyticSettings(4);
    settings.shadowMode = shadowMode;
    settings.shadowSteps = 500;
    settings.lightCount = 1;
    for (int i = 0; i < TRACE_SLOTS; ++i)
        driver.params[static_cast<size_t>(TRACE_SLOT + i)] = traceSettingsSlot(settings, i);
    Light overhead{vec3(0, 1, 0), vec3(1), 8};
    for (int i = 0; i < LIGHT_SLOTS; ++i) driver.params[static_cast<size_t>(LIGHT_SLOT + i)] = lightSlot(overhead, i);
    vec3 eye(3, 0.5, 0);
    vec3 forward = normalize3(-eye);
    vec3 right = normalize3(cross3(forward, vec3(0, 1, 0)));
    Camera camera{eye, forward, right, cross3(right, forward), 0.5};
    for (int i = 0; i < CAMERA_SLOTS; ++i) driver.params[static_cast<size_t>(CAMERA_SLOT + i)] = cameraSlot(camera, i);
    TraceState s = driver.traceSample(5, 5, 10, 10);
    EXPECT_TRUE(s.hit);
    EXPECT_NEAR(s.t, length3(eye), 1e-4);  // the floor at the origin, under the box
    return s.color;
}

TEST(RayTreeShadows, ATransparentOccluderLetsKtMtThroughInEveryShadowMode) {
    Material glass = glassMaterial();
    glass.transparency = 0.8;
    glass.transmissionColor = vec3(1, 0.5, 0.25);
    Material opaque = noMaterial();
    for (int mode : {SHADOW_HARD, SHADOW_SOFT, SHADOW_IMPROVED}) {
        vec3 through = floorUnderBox(glass, mode);
        EXPECT_NEAR(through.x, 0.8, 1e-6) << mode;
        EXPECT_NEAR(through.y, 0.4, 1e-6) << mode;
        EXPECT_NEAR(through.z, 0.2, 1e-6) << mode;
        vec3 blocked = floorUnderBox(opaque, mode);
        EXPECT_EQ(blocked, vec3(0)) << mode << ": no transparent occluder shadows more than an opaque one";
    }
    vec3 open = floorUnderBox(glass, SHADOW_NONE);
    EXPECT_NEAR(open.x, 1, 1e-6);
}

TEST(RayTreeBound, IsTheTracersBoundPerRayOfTheFullTreeUnderTheCap) {
    TraceSettings s{};
    s.maxSteps = 100;
    s.shadowMode = SHADOW_NONE;
    s.lightCount = 1;
    s.maxDepth = 0;
    EXPECT_EQ(rayTreeIterationBound(s), traceIterationBound(s));
    s.maxDepth = 2;
    EXPECT_EQ(rayTreeIterationBound(s), 7 * traceIterationBound(s));
    s.maxDepth = MAX_TRACE_DEPTH;
    s.maxSteps = 8192;
    s.shadowMode = SHADOW_SOFT;
    s.lightCount = 8;
    EXPECT_EQ(rayTreeIterationBound(s), RAY_TREE_ITERATION_CAP);
    EXPECT_LT(RAY_TREE_ITERATION_CAP, 65535);
}

}  // namespace
}  // namespace sdfwb::sdf::f64

namespace sdfwb::sdf::f64 {
namespace {

// A perfect mirror ball at the origin seen from -x: the centre pixel's ray
// comes straight back along -x, which the latitude-longitude map puts at
// u = 1/4, v = 1/2. An 8 x 8 map (one level of detail for this 10-pixel
// camera) holds a known colour in the 2 x 2 texels around that point, so
// bilinear filtering returns it exactly, and the mirror adds all of it.
TEST(EnvironmentSamples, AMirrorBallShowsTheEquirectTexelItReflects) {
    const int side = 8;
    const vec4 known(0.25, 0.5, 0.75, 1);
    std::vector<vec4> level0;
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            bool around = (column == 1 || column == 2) && (row == 3 || row == 4);
            level0.push_back(around ? known : vec4(column / 8.0, row / 8.0, 1, 1));
        }
    }
    std::vector<vec4> texels = level0;
    texels.resize(static_cast<size_t>(mipPyramidTexels(side)), vec4(9, 9, 9, 1));  // coarser levels: not read
    Material mirror = noMaterial();
    mirror.reflectivity = 1;
    mirror.reflectionColor = vec3(1);
    auto field = [&](vec3 p) { return shapeSample(length3(p) - 1, mirror); };
    AnalyticDriver driver{std::vector<vec4>(static_cast<size_t>(MATERIAL_SLOT), vec4(0)), field, texels};
    TraceSettings settings = analyticSettings(2);
    for (int i = 0; i < TRACE_SLOTS; ++i)
        driver.params[static_cast<size_t>(TRACE_SLOT + i)] = traceSettingsSlot(settings, i);
    driver.params[static_cast<size_t>(ENVIRONMENT_SLOT)] =
        environmentSlot(EnvironmentMap{ENVIRONMENT_EQUIRECT, side, 4, 1.0}, 0);
    vec3 eye(-3, 0, 0);
    vec3 forward(1, 0, 0);
    vec3 right = normalize3(cross3(forward, vec3(0, 1, 0)));
    Camera camera{eye, forward, right, cross3(right, forward), 0.05};
    for (int i = 0; i < CAMERA_SLOTS; ++i) driver.params[static_cast<size_t>(CAMERA_SLOT + i)] = cameraSlot(camera, i);
    TraceState s = driver.traceSample(5, 5, 10, 10);
    EXPECT_NEAR(s.color.x, known.x, 1e-9);
    EXPECT_NEAR(s.color.y, known.y, 1e-9);
    EXPECT_NEAR(s.color.z, known.z, 1e-9);
}

}  // namespace
}  // namespace sdfwb::sdf::f64

namespace sdfwb::sdf::f64 {
namespace {

// A white floor y = 0 lit by one light, seen from straight above, whose
// material's bump height is height(p): the colour is N'.L of the bumped normal.
vec3 bumpedFloor(std::function<double(vec3)> height, vec3 towardsLight) {
    auto field = [&](vec3 p) {
        Material m = noMaterial();
        m.diffuse = vec3(1);
        m.bump = height(p);
        return shapeSample(p.y, m);
    };
    AnalyticDriver driver{std::vector<vec4>(static_cast<size_t>(MATERIAL_SLOT), vec4(0)), field};
    TraceSettings settings = analyticSettings(0);
    settings.lightCount = 1;
    for (int i = 0; i < TRACE_SLOTS; ++i)
        driver.params[static_cast<size_t>(TRACE_SLOT + i)] = traceSettingsSlot(settings, i);
    Light light{normalize3(towardsLight), vec3(1), 8};
    for (int i = 0; i < LIGHT_SLOTS; ++i) driver.params[static_cast<size_t>(LIGHT_SLOT + i)] = lightSlot(light, i);
    Camera camera{vec3(0, 2, 0), vec3(0, -1, 0), vec3(1, 0, 0), vec3(0, 0, -1), 0.5};
    for (int i = 0; i < CAMERA_SLOTS; ++i) driver.params[static_cast<size_t>(CAMERA_SLOT + i)] = cameraSlot(camera, i);
    TraceState s = driver.traceSample(5, 5, 10, 10);
    EXPECT_TRUE(s.hit);
    return s.color;
}

TEST(BumpSamples, AConstantHeightFieldLeavesTheNormalUnchanged) {
    vec3 towards(1, 2, 0.5);
    vec3 flat = bumpedFloor([](vec3) { return 0.0; }, towards);
    EXPECT_NEAR(flat.x, normalize3(towards).y, 1e-9);
    for (double c : {0.02, -3.0, 17.5}) {
        EXPECT_EQ(bumpedFloor([c](vec3) { return c; }, towards), flat) << c;
    }
}

// h = k x: the notes' n' = normalize((t_u + d_u n) x (t_v + d_v n)) with
// t_u = x, t_v = -z, d_u = k, d_v = 0 is normalize(-k, 1, 0).
TEST(BumpSamples, ALinearHeightFieldTiltsTheNormalAsTheNotesGiveIt) {
    vec3 towards = normalize3(vec3(1, 1, 0.3));
    for (double k : {0.1, 0.5, -0.8}) {
        vec3 tilted = normalize3(vec3(-k, 1, 0));
        vec3 c = bumpedFloor([k](vec3 p) { return k * p.x; }, towards);
        EXPECT_NEAR(c.x, dot3(tilted, towards), 1e-6) << k;
    }
}

TEST(BumpHeights, StayInRangeAndFadeToTheirMeanWithTheFootprint) {
    for (int pattern : {BUMP_NOISE, BUMP_WAVES}) {
        double spread = 0;
        for (int i = 0; i < 200; ++i) {
            vec3 x(0.37 * i, 0.11 * i, -0.23 * i);
            double fine = bumpHeight(pattern, x, 0.0);
            EXPECT_GE(fine, 0.0);
            EXPECT_LE(fine, 1.0);
            spread = std::max(spread, std::abs(fine - 0.5));
            EXPECT_NEAR(bumpHeight(pattern, x, 2.0), 0.5, 1e-12) << pattern;  // a footprint of two features
        }
        EXPECT_GT(spread, 0.3) << pattern;
    }
    EXPECT_EQ(bumpHeight(BUMP_NONE, vec3(1, 2, 3), 0.0), 0.0);
}

}  // namespace
}  // namespace sdfwb::sdf::f64
