// Included by shared.h once per precision, with SDFWB_SHARED_NS and
// SDFWB_SHARED_REAL defined. No include guard on purpose.
namespace SDFWB_SHARED_NS {

using real = SDFWB_SHARED_REAL;
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using vec4 = glm::vec<4, real>;

using glm::abs;
using glm::cos;
using glm::exp2;
using glm::floatBitsToInt;
using glm::floor;
using glm::intBitsToFloat;
using glm::inversesqrt;
using glm::log2;
using glm::sin;
using std::sqrt;

// min, max and clamp where an operand is NaN, which GLSL leaves undefined: the
// other operand (IEEE 754 minNum/maxNum), as llvmpipe computes them and GPUs'
// min/max instructions do; glm::min would return its first operand. For other
// operands these are glm's (b < a ? b : a), signed zeros included.
SHARED_FN real min(real a, real b) { return b < a || a != a ? b : a; }
SHARED_FN real max(real a, real b) { return a < b || a != a ? b : a; }
SHARED_FN real clamp(real x, real lo, real hi) { return min(max(x, lo), hi); }
template <glm::length_t L>
SHARED_FN glm::vec<L, real> min(glm::vec<L, real> a, glm::vec<L, real> b) {
    for (glm::length_t i = 0; i < L; ++i) a[i] = min(a[i], b[i]);
    return a;
}
template <glm::length_t L>
SHARED_FN glm::vec<L, real> max(glm::vec<L, real> a, glm::vec<L, real> b) {
    for (glm::length_t i = 0; i < L; ++i) a[i] = max(a[i], b[i]);
    return a;
}
template <glm::length_t L>
SHARED_FN glm::vec<L, real> clamp(glm::vec<L, real> x, glm::vec<L, real> lo, glm::vec<L, real> hi) {
    return min(max(x, lo), hi);
}
SHARED_FN int min(int a, int b) { return b < a ? b : a; }
SHARED_FN int max(int a, int b) { return a < b ? b : a; }
SHARED_FN int clamp(int x, int lo, int hi) { return min(max(x, lo), hi); }

#include "sdf/glsl/math.glsl"
#include "sdf/glsl/transcendental.glsl"

// The library's own sin and cos (twist, bend, displacement): in float the
// shared ones, bit for bit with GLSL (whose prelude maps these names to
// them); in double the C library's, so the reference keeps double accuracy.
SHARED_FN real librarySin(real x) {
    if constexpr (sizeof(real) == sizeof(float)) return formulaSin(x);
    return std::sin(x);
}
SHARED_FN real libraryCos(real x) {
    if constexpr (sizeof(real) == sizeof(float)) return formulaCos(x);
    return std::cos(x);
}
// Likewise exp2 and log2 of the exponential and power blends (operators.glsl).
SHARED_FN real libraryExp2(real x) {
    if constexpr (sizeof(real) == sizeof(float)) return formulaExp2(x);
    return std::exp2(x);
}
SHARED_FN real libraryLog2(real x) {
    if constexpr (sizeof(real) == sizeof(float)) return formulaLog2(x);
    return std::log2(x);
}
// And atan2 of the environment map's angles (environment.glsl).
SHARED_FN real libraryAtan2(real y, real x) {
    if constexpr (sizeof(real) == sizeof(float)) return formulaAtan2(y, x);
    return std::atan2(y, x);
}
// in dependency order: clang-format off keeps it
// clang-format off
#include "sdf/glsl/primitives.glsl"
#include "sdf/glsl/operators.glsl"
#include "sdf/glsl/material.glsl"
#include "sdf/glsl/texture.glsl"
#include "sdf/glsl/environment.glsl"
#include "sdf/glsl/texture_mapping.glsl"
#include "sdf/glsl/camera.glsl"
#include "sdf/glsl/instructions.glsl"
#include "sdf/glsl/parameter_blocks.glsl"
#include "sdf/glsl/tracer.glsl"
#include "sdf/glsl/ray_tree.glsl"
#include "sdf/glsl/prune_grid.glsl"
// clang-format on

}  // namespace SDFWB_SHARED_NS
