// Shared math: compiles as GLSL 3.30 and as C++20 over GLM (see sdf/shared_cpp.h).
// Rules of this subset: scalar type `real`, literals `real(0.5)`, no swizzles,
// no out/inout, no arrays, guards wherever GLSL leaves a result undefined.
// Built-ins whose bits differ between llvmpipe and GLM (dot, normalize, length,
// mix, smoothstep, round) are replaced by versions with a fixed evaluation order.

const real PI = real(3.14159265358979);

// The first three components of a parameter slot.
SHARED_FN vec3 xyz(vec4 q) { return vec3(q.x, q.y, q.z); }

SHARED_FN real dot2(vec2 a, vec2 b) { return a.x * b.x + a.y * b.y; }
SHARED_FN real dot3(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
SHARED_FN real length2d(vec2 a) { return sqrt(dot2(a, a)); }
SHARED_FN real length3(vec3 a) { return sqrt(dot3(a, a)); }

// normalize(0) is undefined in GLSL: return +z instead.
SHARED_FN vec3 normalize3(vec3 a) {
    real lengthSquared = dot3(a, a);
    if (lengthSquared > real(0)) {
        return a * inversesqrt(lengthSquared);
    }
    return vec3(real(0), real(0), real(1));
}

SHARED_FN vec3 cross3(vec3 a, vec3 b) {
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

SHARED_FN real lerpr(real a, real b, real w) { return a + (b - a) * w; }
SHARED_FN vec3 lerp3(vec3 a, vec3 b, vec3 w) { return a + (b - a) * w; }
SHARED_FN vec3 lerp3s(vec3 a, vec3 b, real w) { return a + (b - a) * w; }

SHARED_FN real saturate(real x) { return min(max(x, real(0)), real(1)); }

// GLSL's smoothstep is undefined for edge0 >= edge1. Equal edges give
// step(edge0, x), as in formulas (docs/shared-glsl-subset.md, built-in guards).
SHARED_FN real smoothstepr(real edge0, real edge1, real x) {
    if (edge0 == edge1) {
        return x < edge0 ? real(0) : real(1);
    }
    real t = saturate((x - edge0) / (edge1 - edge0));
    return t * t * (real(3) - real(2) * t);
}

SHARED_FN real safeSqrt(real x) { return sqrt(max(x, real(0))); }

// GLSL mod (x - y*floor(x/y)); mod(x, 0) is undefined, here it returns x.
SHARED_FN real modr(real x, real y) {
    if (y == real(0)) {
        return x;
    }
    return x - y * floor(x / y);
}

// round() rounds halves differently on llvmpipe and in GLM.
SHARED_FN real roundHalfUp(real x) { return floor(x + real(0.5)); }

// pow with a non-positive base is undefined in GLSL; bases here are clamped to >= 0
// and pow(0, y) with y > 0 is 0.
SHARED_FN real safePow(real base, real exponent) {
    if (base <= real(0)) {
        return real(0);
    }
    return exp2(exponent * log2(base));
}
