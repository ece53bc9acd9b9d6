// Included by shared.h once per precision, with SDFWB_SHARED_NS and
// SDFWB_SHARED_REAL defined. No include guard on purpose.
namespace SDFWB_SHARED_NS {

using real = SDFWB_SHARED_REAL;
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using vec4 = glm::vec<4, real>;

using glm::abs;
using glm::clamp;
using glm::cos;
using glm::exp2;
using glm::floatBitsToInt;
using glm::floor;
using glm::intBitsToFloat;
using glm::inversesqrt;
using glm::log2;
using glm::max;
using glm::min;
using glm::sin;
using std::sqrt;

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
#include "sdf/glsl/primitives.glsl"
#include "sdf/glsl/operators.glsl"
#include "sdf/glsl/material.glsl"
#include "sdf/glsl/texture.glsl"
#include "sdf/glsl/camera.glsl"
#include "sdf/glsl/instructions.glsl"
#include "sdf/glsl/parameter_blocks.glsl"
#include "sdf/glsl/tracer.glsl"
#include "sdf/glsl/ray_tree.glsl"
#include "sdf/glsl/prune_grid.glsl"

}  // namespace SDFWB_SHARED_NS
