// Shading, shadows and ambient occlusion on scenes with known answers (as
// pbrt-v4's integrator tests do): each pixel of a CPU render in double is
// compared with the value worked out in closed form from the ray's exact
// intersection with spheres and planes. The tolerances cover the hit epsilon
// (the march stops within it of the surface, the normal is sampled there).

#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/interpreter.h"
#include "program/compile_scene.h"
#include "scene/camera_frame.h"
#include "scene/scene.h"

namespace sdfwb {
namespace {

using glm::dvec3;
using scene::Node;
using scene::NodeKind;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// A scene with no light but what a test adds, no ambient light, and a tight
// epsilon; the default material is `material`.
scene::Scene emptyScene(const scene::Material& material) {
    scene::Scene s;
    s.render.width = kWidth;
    s.render.height = kHeight;
    s.render.aa = 1;
    s.render.epsilon = 1e-5;
    s.render.maxSteps = 1024;
    s.render.shadows = scene::ShadowMode::None;
    s.render.aoSamples = 0;
    s.environment.ambient = dvec3(0);
    s.environment.background = dvec3(0.2, 0.4, 0.6);
    s.lights.clear();
    scene::Material named = material;
    named.name = "surface";
    s.materials.push_back(named);
    return s;
}

Node shape(NodeKind kind, const std::string& material = "surface") {
    Node n = Node::make(kind);
    n.set("material", material);
    return n;
}

Node plane(dvec3 normal, double offset) {
    Node n = shape(NodeKind::Plane);
    n.set("normal", normal);
    n.set("offset", offset);
    return n;
}

Node sphereAt(dvec3 centre, double radius) {
    Node sphere = shape(NodeKind::Sphere);
    sphere.set("radius", radius);
    Node translate = Node::make(NodeKind::Translate);
    translate.set("offset", centre);
    translate.children.push_back(sphere);
    return translate;
}

// Ambient and diffuse only (no specular highlight), for the shadow and
// occlusion tests: L_A + S (R_A + R_D n.l) where lit, L_A in shadow.
scene::Material matte() {
    scene::Material m;
    m.ambient = dvec3(0.1);
    m.diffuse = dvec3(0.7, 0.6, 0.5);
    m.specular = dvec3(0);
    return m;
}

// A pixel's primary ray in world coordinates, as the CPU renderer shoots it.
struct WorldRay {
    dvec3 origin;
    dvec3 direction;  // unit
};

struct Render {
    program::Program program;
    image::Frame frame;
    dvec3 eye;

    WorldRay ray(int x, int y) const {
        cpu::f64::Kernel kernel(program);
        double px = x + 0.5 + cpu::f64::Kernel::offset(0, 1);
        double py = (program.height - 1 - y) + 0.5 + cpu::f64::Kernel::offset(0, 1);
        cpu::f64::Ray r = kernel.ray(px, py);
        return {r.origin + eye, glm::normalize(dvec3(r.direction))};
    }
    dvec3 color(int x, int y) const {
        const float* c = &frame.color.rgb[3 * (static_cast<size_t>(y) * kWidth + static_cast<size_t>(x))];
        return dvec3(c[0], c[1], c[2]);
    }
};

Render render(const scene::Scene& s) {
    Render r{program::compileScene(s), {}, scene::cameraFrame(s.camera).eye};
    render::RenderControl control;
    control.precision = render::Precision::Double;
    r.frame = cpu::renderCpu(r.program, control).frame;
    return r;
}

// The first t > 0 where the ray meets the sphere, if it does.
std::optional<double> hitSphere(const WorldRay& ray, dvec3 centre, double radius) {
    dvec3 oc = ray.origin - centre;
    double b = glm::dot(oc, ray.direction), c = glm::dot(oc, oc) - radius * radius;
    double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    double t = -b - std::sqrt(disc);
    return t > 0 ? std::optional(t) : std::nullopt;
}

// Where the ray enters the solid below the plane dot(p, n) = offset, if it does.
std::optional<double> hitPlane(const WorldRay& ray, dvec3 normal, double offset) {
    double towards = glm::dot(ray.direction, normal);
    if (towards >= 0) return std::nullopt;
    double t = (offset - glm::dot(ray.origin, normal)) / towards;
    return t > 0 ? std::optional(t) : std::nullopt;
}

// L_A + L_E + S (R_A + R_D n.l + R_E n.l spec^alpha), Blinn-Phong or Phong (thesis, Definition 2.4).
dvec3 localShading(const scene::Material& m, dvec3 normal, dvec3 toViewer, dvec3 lightDirection, dvec3 lightColor,
                   scene::LightingModel model) {
    double nl = std::max(glm::dot(normal, lightDirection), 0.0);
    double base = model == scene::LightingModel::Phong
                      ? glm::dot(2.0 * glm::dot(normal, lightDirection) * normal - lightDirection, toViewer)
                      : glm::dot(normal, glm::normalize(lightDirection + toViewer));
    double specular = nl * std::pow(std::max(base, 0.0), m.shininess);
    return m.emission * m.emissionStrength + lightColor * (m.ambient + m.diffuse * nl + m.specular * specular);
}

double largestComponent(dvec3 v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }

struct ShadingCheck {
    int checked = 0;   // pixels compared
    double worst = 0;  // largest channel difference
};

// Each pixel whose ray meets the sphere away from its silhouette, and whose
// exact normal n has n.l >= minLight, against the local model at n.
ShadingCheck compareWithLocalShading(const Render& r, const scene::Material& m, dvec3 centre, double radius,
                                     const scene::Light& light, scene::LightingModel model, double minLight) {
    const dvec3 l = glm::normalize(light.direction);
    ShadingCheck check;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            WorldRay ray = r.ray(x, y);
            std::optional<double> t = hitSphere(ray, centre, radius);
            if (!t) continue;
            dvec3 n = glm::normalize(ray.origin + ray.direction * *t - centre);
            if (glm::dot(n, -ray.direction) < 0.25 || glm::dot(n, l) < minLight) continue;
            dvec3 expected = localShading(m, n, -ray.direction, l, light.color, model);
            check.worst = std::max(check.worst, largestComponent(r.color(x, y) - expected));
            ++check.checked;
        }
    }
    return check;
}

TEST(AnalyticShading, ASphereIsShadedByTheLocalModelAtItsExactNormals) {
    scene::Material m;
    m.ambient = dvec3(0.1, 0.05, 0.02);
    m.diffuse = dvec3(0.6, 0.3, 0.2);
    m.specular = dvec3(0.3);
    m.shininess = 16;
    m.emission = dvec3(0.02, 0, 0);
    m.emissionStrength = 2;
    const dvec3 centre(0, 0.5, 0);
    const double radius = 1.2;
    const dvec3 lightColor(1, 0.9, 0.8);
    for (scene::LightingModel model : {scene::LightingModel::BlinnPhong, scene::LightingModel::Phong}) {
        SCOPED_TRACE(scene::kLightingModelNames[static_cast<int>(model)]);
        scene::Scene s = emptyScene(m);
        s.render.lighting = model;
        s.lights.push_back({.direction = dvec3(0.5, 0.8, 0.3), .color = lightColor, .softness = 8});
        s.root.children.push_back(sphereAt(centre, radius));
        ShadingCheck check = compareWithLocalShading(render(s), m, centre, radius, s.lights[0], model, -1);
        EXPECT_GT(check.checked, kWidth * kHeight / 8);
        EXPECT_LT(check.worst, 2e-4) << check.checked << " pixels";
    }
}

TEST(AnalyticShading, MissedRaysShowTheBackground) {
    scene::Scene s = emptyScene(scene::Material{});
    s.lights.push_back({});
    s.root.children.push_back(sphereAt(dvec3(0, 0.5, 0), 1.0));
    Render r = render(s);
    int checked = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            WorldRay ray = r.ray(x, y);
            // rays that pass the sphere by more than a hundredth
            if (hitSphere(ray, dvec3(0, 0.5, 0), 1.01)) continue;
            EXPECT_EQ(r.color(x, y), dvec3(glm::vec3(s.environment.background))) << x << ", " << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, kWidth * kHeight / 4);
}

// A sphere over the floor, the light straight above: a hard shadow is the
// disc under the sphere, where only the ambient light and emission remain.
TEST(AnalyticShading, AHardShadowIsTheDiscUnderTheSphere) {
    const scene::Material m = matte();
    scene::Scene s = emptyScene(m);
    s.environment.ambient = dvec3(0.05);
    s.render.shadows = scene::ShadowMode::Hard;
    s.camera = {.target = {0, 0, 0}, .azimuth = 20, .elevation = 55, .distance = 6, .fov = 50};
    s.lights.push_back({.direction = dvec3(0, 1, 0), .color = dvec3(1), .softness = 8});
    const dvec3 centre(0, 1.5, 0);
    const double radius = 0.75;
    s.root.children.push_back(plane(dvec3(0, 1, 0), 0));
    s.root.children.push_back(sphereAt(centre, radius));
    Render r = render(s);
    const dvec3 shadowed = s.environment.ambient;
    const dvec3 lit = s.environment.ambient + m.ambient + m.diffuse;
    int inShadow = 0, inLight = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            WorldRay ray = r.ray(x, y);
            std::optional<double> t = hitPlane(ray, dvec3(0, 1, 0), 0);
            if (!t || hitSphere(ray, centre, radius * 1.02)) continue;
            dvec3 g = ray.origin + ray.direction * *t;
            double fromAxis = std::hypot(g.x - centre.x, g.z - centre.z);
            if (fromAxis < radius * 0.95) {
                EXPECT_LT(largestComponent(r.color(x, y) - shadowed), 1e-6) << "shadowed " << x << ", " << y;
                ++inShadow;
            } else if (fromAxis > radius * 1.05 && *t < 40) {
                EXPECT_LT(largestComponent(r.color(x, y) - lit), 1e-6) << "lit " << x << ", " << y;
                ++inLight;
            }
        }
    }
    EXPECT_GT(inShadow, 40);
    EXPECT_GT(inLight, 400);
}

// A distance formula may bound the distance loosely (a field divided by a
// Lipschitz constant larger than it needed reads less than the distance),
// and its shadow rays must still leave its surface: starting them a fixed
// multiple of epsilon off it, where such a field reads under epsilon, called
// them blocked there, and the lit side of a lumpy stone had black spots.
TEST(AnalyticShading, AFieldBelowTheDistanceCastsNoShadowOnItsOwnLitSide) {
    const scene::Material m = matte();
    const double radius = 1.2;
    const dvec3 lightColor(1, 0.9, 0.8);
    for (scene::ShadowMode mode : {scene::ShadowMode::Hard, scene::ShadowMode::Soft}) {
        SCOPED_TRACE(scene::kShadowModeNames[static_cast<int>(mode)]);
        scene::Scene s = emptyScene(m);
        s.render.shadows = mode;
        s.render.epsilon = 1e-3;
        s.lights.push_back({.direction = dvec3(0.5, 0.8, 0.3), .color = lightColor, .softness = 8});
        Node bound = shape(NodeKind::Sdf);
        bound.set("formula", std::string("0.4 * (length(p) - 1.2)"));
        s.root.children.push_back(bound);
        // the lit side away from the terminator, where the field's penumbra
        // estimate k 0.4 d / t stays over 1
        ShadingCheck check =
            compareWithLocalShading(render(s), m, dvec3(0), radius, s.lights[0], s.render.lighting, 0.5);
        EXPECT_GT(check.checked, kWidth * kHeight / 16);
        EXPECT_LT(check.worst, 5e-3) << check.checked << " pixels";
    }
}

// The same loose field's ambient occlusion: along the normal of a convex
// surface nothing occludes (ao = 1), and a field reading 0.4 of the distance
// there darkened the whole sphere (ao 0.79 with these 5 samples).
TEST(AnalyticShading, AFieldBelowTheDistanceDoesNotOccludeItsOwnConvexSide) {
    const scene::Material m = matte();
    scene::Scene s = emptyScene(m);
    s.render.epsilon = 1e-3;
    s.render.aoSamples = 5;
    s.render.aoDistance = 0.5;
    s.lights.push_back({.direction = dvec3(0.5, 0.8, 0.3), .color = dvec3(1, 0.9, 0.8), .softness = 8});
    Node bound = shape(NodeKind::Sdf);
    bound.set("formula", std::string("0.4 * (length(p) - 1.2)"));
    s.root.children.push_back(bound);
    ShadingCheck check = compareWithLocalShading(render(s), m, dvec3(0), 1.2, s.lights[0], s.render.lighting, -1);
    EXPECT_GT(check.checked, kWidth * kHeight / 8);
    EXPECT_LT(check.worst, 5e-3) << check.checked << " pixels";
}

// The floor y = 0 against the wall x = 0: at a floor point x from the wall
// the AO samples at heights h_i = i D / M are min(h_i, x) from the surface,
// so ao = 1 - sum_i 2^-i (h_i - min(h_i, x)) / D (thesis, Algorithm 15).
TEST(AnalyticShading, AmbientOcclusionInACornerFollowsTheWallDistance) {
    scene::Material m;
    m.ambient = dvec3(0);
    m.diffuse = dvec3(0.8);
    m.specular = dvec3(0);
    scene::Scene s = emptyScene(m);
    s.render.aoSamples = 5;
    s.render.aoDistance = 1.5;
    s.camera = {.target = {1.2, 0, 0}, .azimuth = 90, .elevation = 35, .distance = 5, .fov = 50};
    s.lights.push_back({.direction = dvec3(0, 1, 0), .color = dvec3(1), .softness = 8});
    s.root.children.push_back(plane(dvec3(0, 1, 0), 0));
    s.root.children.push_back(plane(dvec3(1, 0, 0), 0));
    Render r = render(s);
    ASSERT_GT(r.eye.x, 0.0);
    ASSERT_GT(r.eye.y, 0.0);
    auto expectedAo = [&](double x) {
        double occlusion = 0, weight = 0.5;
        for (int i = 1; i <= s.render.aoSamples; ++i) {
            double h = i * s.render.aoDistance / s.render.aoSamples;
            occlusion += weight * (h - std::min(h, x));
            weight *= 0.5;
        }
        return std::clamp(1.0 - occlusion / s.render.aoDistance, 0.0, 1.0);
    };
    int checked = 0, occluded = 0;
    double worst = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            WorldRay ray = r.ray(x, y);
            std::optional<double> floor = hitPlane(ray, dvec3(0, 1, 0), 0);
            std::optional<double> wall = hitPlane(ray, dvec3(1, 0, 0), 0);
            if (!floor || (wall && *wall < *floor) || *floor > 40) continue;
            double fromWall = (ray.origin + ray.direction * *floor).x;
            if (fromWall < 0.01) continue;  // the normal's samples reach the wall
            double ao = expectedAo(fromWall);
            worst = std::max(worst, largestComponent(r.color(x, y) - m.diffuse * ao));
            ++checked;
            occluded += ao < 0.95 ? 1 : 0;
        }
    }
    EXPECT_GT(checked, 400);
    EXPECT_GT(occluded, 100) << "the corner's occlusion is in view";
    EXPECT_LT(worst, 1e-4);
}

}  // namespace
}  // namespace sdfwb
