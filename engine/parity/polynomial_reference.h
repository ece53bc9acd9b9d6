#pragma once
// The reference for polynomial surfaces: along each primary ray, the first
// point of the solid {F <= 0} clipped to the node's bounding box: the box entry
// when F <= 0 there, else the first root of the univariate polynomial
// F(o + t d) inside the box, found by Bernstein subdivision (a root is isolated
// to 1e-12 of the segment, or a segment is proved root-free by the convex hull
// of its Bernstein coefficients). The live method (sphere tracing
// |F| / |grad F| with a step clamp, sdf/glsl/instructions.glsl) is measured
// against it.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace sdfwb::parity {

// A polynomial in x, y, z with double coefficients (from the exact one).
struct PolynomialTerms {
    std::vector<double> coefficients;
    std::vector<std::array<int, 3>> exponents;
};
PolynomialTerms polynomialTerms(const std::string& formula);

// Coefficients c[k] of t^k of F(origin + t direction).
std::vector<double> alongRay(const PolynomialTerms& f, const glm::dvec3& origin, const glm::dvec3& direction);

// The smallest root of the power-basis polynomial `c` in [t0, t1], if any.
std::optional<double> firstRoot(const std::vector<double>& c, double t0, double t1);

// Whether the scene is a solid polynomial node (no sheet) under translations
// only, without ground (what the reference handles); the node and its world
// offset when it is.
struct PolynomialScene {
    const scene::Node* node = nullptr;
    glm::dvec3 offset{0.0};  // world position of the node's origin
};
std::optional<PolynomialScene> polynomialScene(const scene::Scene& scene);

struct PolynomialAccuracy {
    size_t pixels = 0;
    size_t referenceHits = 0;
    size_t holes = 0;           // reference hit, live missed
    size_t falseHits = 0;       // reference missed, live hit
    size_t interiorHoles = 0;   // holes whose 8 neighbours all hit in the reference
    size_t interiorFalseHits = 0;  // false hits whose 8 neighbours all miss in the reference
    double meanRelativeDepthError = 0;  // |t_live - t_ref| / t_ref over pixels both hit
    double maxRelativeDepthError = 0;
};

// Reference first-root distances for every pixel centre (AA 1) of a
// width x height view of `scene` (which must satisfy polynomialScene).
std::vector<std::optional<double>> referenceDepths(const scene::Scene& scene, int width, int height);

// Compares a live frame rendered at AA 1 with the reference depths.
PolynomialAccuracy measureAccuracy(const std::vector<std::optional<double>>& reference, const image::Frame& live);

std::string describeAccuracy(const std::string& label, const PolynomialAccuracy& accuracy);

}  // namespace sdfwb::parity
