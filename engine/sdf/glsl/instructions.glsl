// One function per instruction of the compiled scene (engine/program/opcodes.h):
// the GLSL generator emits a call to it, the CPU evaluator makes the same call,
// so an instruction means the same thing in both backends. Parameters arrive as
// the vec4 slots of the parameter buffer; layouts are listed in opcodes.h.

// ---- Point: P[dst] = f(P[a], slots) ----
SHARED_FN vec3 instTranslate(vec3 p, vec4 q0) { return opTranslate(p, xyz(q0)); }
SHARED_FN vec3 instRotate(vec3 p, vec4 q0, vec4 q1, vec4 q2) { return opRotate(p, xyz(q0), xyz(q1), xyz(q2)); }
SHARED_FN vec3 instScale(vec3 p, vec4 q0) { return opScale(p, q0.x); }
SHARED_FN vec3 instTwist(vec3 p, vec4 q0) { return opTwist(p, q0.x); }
SHARED_FN vec3 instBend(vec3 p, vec4 q0) { return opBend(p, q0.x); }
SHARED_FN vec3 instElongate(vec3 p, vec4 q0) { return opElongate(p, xyz(q0)); }
SHARED_FN vec3 instMirror(vec3 p, vec4 q0) { return opMirror(p, xyz(q0)); }
SHARED_FN vec3 instRepeat(vec3 p, vec4 q0, vec4 q1) { return opRepeat(p, xyz(q0), xyz(q1)); }
SHARED_FN vec3 instRepeatInfinite(vec3 p, vec4 q0) { return opRepeatInfinite(p, xyz(q0)); }

// ---- Shape: S[dst] = shapeSample(f(P[a], slots), material) ----
SHARED_FN real instSphere(vec3 p, vec4 q0) { return sdSphere(p, q0.x); }
SHARED_FN real instBox(vec3 p, vec4 q0) { return sdBox(p, xyz(q0)); }
SHARED_FN real instRoundBox(vec3 p, vec4 q0) { return sdRoundBox(p, xyz(q0), q0.w); }
SHARED_FN real instPlane(vec3 p, vec4 q0) { return sdPlane(p, xyz(q0), q0.w); }
SHARED_FN real instTorus(vec3 p, vec4 q0) { return sdTorus(p, q0.x, q0.y); }
SHARED_FN real instCone(vec3 p, vec4 q0) { return sdCone(p, vec2(q0.x, q0.y), q0.z); }
SHARED_FN real instEllipsoid(vec3 p, vec4 q0) { return sdEllipsoid(p, xyz(q0)); }
SHARED_FN real instCylinder(vec3 p, vec4 q0) { return sdCylinder(p, q0.x, q0.y); }
SHARED_FN real instCapsule(vec3 p, vec4 q0, vec4 q1) { return sdCapsule(p, xyz(q0), xyz(q1), q0.w); }

// Formula shapes: the formula's value, or value and gradient v = (F, dF/dx,
// dF/dy, dF/dz), comes from code generated from the user's formula.
SHARED_FN real instSdfFormula(real value) { return value; }

// An implicit surface F = 0 (inside F < 0) inside its bounding box, with the
// distance bound |F| / |grad F| (thesis, Proposition 1.2) clamped to a maximum
// step: the bound is only local, overshooting far from the surface and useless
// where grad F vanishes. q0 = (box centre, max step), q1 = (box half extents,
// half the sheet thickness).
// A gradient shorter than this counts as zero: its squares would be denormal,
// which llvmpipe flushes to zero and the CPU keeps (the backends disagreed
// there, tests/gl/opcode_conformance_test.cpp). 2^-50.
const real IMPLICIT_MIN_GRADIENT = real(8.8817842e-16);
SHARED_FN Sample instImplicit(vec3 p, vec4 v, vec4 q0, vec4 q1, Material material) {
    real box = sdBox(p - xyz(q0), xyz(q1));
    real gradientLength = length3(vec3(v.y, v.z, v.w));
    if (!(gradientLength > IMPLICIT_MIN_GRADIENT)) {
        gradientLength = real(0);
    }
    if (q1.w > real(0)) {
        // A sheet of half-thickness h = q1.w around F = 0 (where grad F = 0,
        // off the surface, it takes a step of max_step). A step that
        // overshoots F = 0 lands inside a solid, but can jump over a sheet:
        // steps stop at max_step and at 2h, the sheet's thickness. The
        // distance is not capped, so max_step < h leaves the sheet as it is,
        // and ambient occlusion and penumbrae see the bound itself.
        real d = q0.w;
        if (gradientLength > real(0)) {
            d = abs(v.x) / gradientLength - q1.w;
        }
        d = max(box, d);
        return Sample(d, max(box, min(d, min(q0.w, real(2) * q1.w))), material);
    }
    real bound = q0.w;  // grad F = 0 off the surface: a step of max_step
    if (gradientLength > real(0)) {
        bound = min(abs(v.x) / gradientLength, q0.w);
    }
    return shapeSample(max(box, v.x < real(0) ? -bound : bound), material);
}

// Farther than any surface: the ground's safe step above the plane (below).
const real GROUND_CLEAR_STEP = real(1e10);

// The ground plane's distance at march point p, its height in march
// coordinates given: the instruction's, the march's along the ray
// (tracer.glsl) and the other phases' step all read it here.
SHARED_FN real heightAboveGround(vec3 p, real groundHeight) { return p.y - groundHeight; }

// The ground's safe step at distance d: taken along the ray, none above the
// plane (the march takes it, tracer.glsl's groundAhead); the prune grid
// bounds it with this too.
SHARED_FN real groundSafeStep(real d, bool alongRay) { return d > real(0) && alongRay ? GROUND_CLEAR_STEP : d; }

// The ground plane y = height, in march coordinates: q0 = (height - eye.y,
// pattern, footprint per distance, 1 when the march takes it along the ray),
// q1 = (eye, cell size), q2 = (second colour, line width). The footprint
// point f (footprint_point.glsl) is the ray's direction times the length of
// its path from the eye: a sample's footprint, a disc of diameter
// w = q0.z |f| across the ray, lands on the plane as an ellipse whose extent
// along x is w sqrt(1 + (f.x / f.y)^2) (and along z likewise), long towards
// the horizon.
// Taken along the ray, its safe step above the plane is GROUND_CLEAR_STEP,
// which never limits the union it ends: the march takes the plane's step
// along the ray instead (tracer.glsl's groundAhead) and the other phases its
// distance (withGroundStep), the scene's other surfaces keeping theirs.
SHARED_FN Sample instGround(vec3 p, vec3 f, vec4 q0, vec4 q1, vec4 q2, Material base) {
    real d = heightAboveGround(p, q0.x);
    real height = abs(f.y);
    real w = q0.z * length3(f);
    vec2 footprint = vec2(PATTERN_MAX_FOOTPRINT * q1.w);
    if (height > real(0)) {
        footprint = vec2(w * sqrt(f.y * f.y + f.x * f.x) / height, w * sqrt(f.y * f.y + f.z * f.z) / height);
    }
    Material m = groundMaterial(base, p + xyz(q1), int(q0.y), q1.w, q2.w, xyz(q2), footprint);
    return Sample(d, groundSafeStep(d, q0.w > real(0)), m);
}

// ---- Combine: S[dst] = f(S[a], S[b], slot); the same operator on both channels ----
SHARED_FN Sample instUnion(Sample a, Sample b) {
    return blendSamples(a, b, hardMin(a.d, b.d), hardMin(a.step, b.step));
}
SHARED_FN Sample instIntersection(Sample a, Sample b) {
    return blendSamples(a, b, hardMax(a.d, b.d), hardMax(a.step, b.step));
}
SHARED_FN Sample instDifference(Sample a, Sample b) {
    return blendSamples(a, b, hardMax(a.d, -b.d), hardMax(a.step, -b.step));
}
// q0 = (k, exponent)
SHARED_FN Sample instSmoothUnion(Sample a, Sample b, vec4 q0, int variant) {
    return blendSamples(a, b, smoothMin(variant, a.d, b.d, q0.x, q0.y), smoothMin(variant, a.step, b.step, q0.x, q0.y));
}
SHARED_FN Sample instSmoothIntersection(Sample a, Sample b, vec4 q0, int variant) {
    return blendSamples(a, b, smoothMax(variant, a.d, b.d, q0.x, q0.y), smoothMax(variant, a.step, b.step, q0.x, q0.y));
}
SHARED_FN Sample instSmoothDifference(Sample a, Sample b, vec4 q0, int variant) {
    return blendSamples(a, b, smoothMax(variant, a.d, -b.d, q0.x, q0.y), smoothMax(variant, a.step, -b.step, q0.x, q0.y));
}

// ---- Post: S[dst] = f(S[a], P[b], slot) ----
SHARED_FN Sample withDistances(Sample s, real d, real step) { return Sample(d, step, s.material); }
SHARED_FN Sample instScaleDistance(Sample s, vec3 p, vec4 q0) { return withDistances(s, s.d * q0.x, s.step * q0.x); }
SHARED_FN Sample instRoundDistance(Sample s, vec3 p, vec4 q0) { return withDistances(s, s.d - q0.x, s.step - q0.x); }
// q0 = (amplitude, frequency, step factor)
SHARED_FN Sample instDisplace(Sample s, vec3 p, vec4 q0) {
    real pattern = displacementPattern(p, q0.x, q0.y);
    return withDistances(s, s.d + pattern, (s.step + pattern) * q0.z);
}
// Twist and bend: only the step shrinks (q0.x = 1 / Lipschitz bound).
SHARED_FN Sample instStepScale(Sample s, vec3 p, vec4 q0) { return withDistances(s, s.d, s.step * q0.x); }

// ---- Texture: S[dst] = f(S[a], P[b], F, slots) ----
// A primitive's sample with its material textured at its object-space point
// p; |f| is the sample's distance from the eye along the ray's path (f the
// footprint point, footprint_point.glsl).
// q0 = (pattern, 1 / scale, footprint per distance in texture units,
// 1 when it changes the specular colour too), q1 = (texture colour, 0).
SHARED_FN Sample instTexture(Sample s, vec3 p, vec3 f, vec4 q0, vec4 q1) {
    real w = q0.z * length3(f);
    return Sample(s.d, s.step, texturedMaterial(s.material, int(q0.x), p * q0.y, w, xyz(q1), q0.w > real(0)));
}

// ---- Bump: S[dst] = f(S[a], P[b], F, slots) ----
// A primitive's sample carrying its bump map's height at its object-space
// point p (texture.glsl), which the tracer differentiates for the shading
// normal. q0 = (pattern, 1 / scale, footprint per distance in bump units, depth).
SHARED_FN Sample instBump(Sample s, vec3 p, vec3 f, vec4 q0) {
    Material m = s.material;
    m.bump = q0.w * bumpHeight(int(q0.x), p * q0.y, q0.z * length3(f));
    return Sample(s.d, s.step, m);
}

// ---- Constant ----
// "Nothing here": far beyond any max distance.
SHARED_FN Sample instEmpty(Material base) { return shapeSample(real(1e10), base); }
