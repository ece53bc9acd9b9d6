// Materials (thesis, Definition 2.2, plus emission) and distance samples that carry them.

struct Material {
    vec3 ambient;   // R_A
    vec3 diffuse;   // R_D
    vec3 specular;  // R_E
    real shininess; // alpha
    vec3 emission;  // L_E
    real emissionStrength;  // multiplies L_E; 1 is the colour as given
    real reflectivity;      // k_ps (ray_tree.glsl)
    vec3 reflectionColor;   // M_PS
    real transparency;      // k_t
    vec3 transmissionColor; // M_T
    real ior;               // index of refraction against the outside's 1
    real fresnel;           // 0: the notes' fixed fractions, 1: Schlick's; a smooth blend mixes them
    real bump;              // the bump map's height at this point, scene units (texture.glsl); 0 without one
};

// ---- Material: (ambient, shininess), (diffuse, ior), (specular, fresnel), (emission, emissionStrength),
// (reflectionColor, reflectivity), (transmissionColor, transparency) ----
SHARED_FN Material materialFromSlots(vec4 q0, vec4 q1, vec4 q2, vec4 q3, vec4 q4, vec4 q5) {
    return Material(xyz(q0), xyz(q1), xyz(q2), q0.w, xyz(q3), q3.w, q4.w, xyz(q4), q5.w, xyz(q5), q1.w, q2.w,
                    real(0));
}
SHARED_FN vec4 materialSlot(Material m, int i) {
    if (i == 0) {
        return vec4(m.ambient, m.shininess);
    }
    if (i == 1) {
        return vec4(m.diffuse, m.ior);
    }
    if (i == 2) {
        return vec4(m.specular, m.fresnel);
    }
    if (i == 3) {
        return vec4(m.emission, m.emissionStrength);
    }
    if (i == 4) {
        return vec4(m.reflectionColor, m.reflectivity);
    }
    return vec4(m.transmissionColor, m.transparency);
}

// No material: what the tracer holds before a hit.
SHARED_FN Material noMaterial() {
    return Material(vec3(real(0)), vec3(real(0)), vec3(real(0)), real(1), vec3(real(0)), real(1), real(0),
                    vec3(real(1)), real(0), vec3(real(1)), real(1), real(0), real(0));
}

SHARED_FN Material mixMaterial(Material a, Material b, real w) {
    if (w <= real(0)) {
        return a;
    }
    if (w >= real(1)) {
        return b;
    }
    return Material(lerp3s(a.ambient, b.ambient, w), lerp3s(a.diffuse, b.diffuse, w),
                    lerp3s(a.specular, b.specular, w), lerpr(a.shininess, b.shininess, w),
                    lerp3s(a.emission, b.emission, w), lerpr(a.emissionStrength, b.emissionStrength, w),
                    lerpr(a.reflectivity, b.reflectivity, w), lerp3s(a.reflectionColor, b.reflectionColor, w),
                    lerpr(a.transparency, b.transparency, w),
                    lerp3s(a.transmissionColor, b.transmissionColor, w), lerpr(a.ior, b.ior, w),
                    lerpr(a.fresnel, b.fresnel, w), lerpr(a.bump, b.bump, w));
}

// A point of the scene's field. `d` is the distance estimate the tracer tests
// hits, shades and shadows with; `step` is a safe step: the same expression
// evaluated on distances divided by the Lipschitz bound of the operators that
// stretch space (twist, bend, displace). So a twisted sphere keeps its size and
// shading, and only the march slows down where space is stretched.
struct Sample {
    real d;
    real step;
    Material material;
};

SHARED_FN Sample shapeSample(real d, Material material) { return Sample(d, d, material); }

// `blend` combines the distances (and gives the material weight), `steps` the safe steps.
SHARED_FN Sample blendSamples(Sample a, Sample b, Blend blend, Blend steps) {
    return Sample(blend.d, steps.d, mixMaterial(a.material, b.material, blend.w));
}

// Ground patterns: 0 plain, 1 checker, 2 grid. The pattern replaces the diffuse
// and ambient colour with `secondColor` on alternate cells or on grid lines.
const int GROUND_PLAIN = 0;
const int GROUND_CHECKER = 1;
const int GROUND_GRID = 2;

// Patterns are box-filtered over the footprint of the sample (lecture notes on
// realism, 1.1: a texture seen from afar must be averaged over what a pixel
// covers, or its cells alias into moire towards the horizon). Each pattern is
// a product of two 1D patterns, and the box filter of a product of functions
// of u and of v is the product of their filters, so each axis is filtered
// exactly from its integral: (I(x + w/2) - I(x - w/2)) / w. Footprints
// narrower than this (in cells) take the point sample, where the difference
// of integrals would be float noise.
const real PATTERN_MIN_FOOTPRINT = real(1e-4);
// Wider footprints are clamped: the filtered value is then the pattern's mean
// to within 1/1000, and the integrals' arguments stay small enough for float.
const real PATTERN_MAX_FOOTPRINT = real(1000);

// The checker's square wave s(x) = 1 on [0, 1), -1 on [1, 2), period 2, and
// its integral from 0, a triangle wave.
SHARED_FN real checkerWave(real x) { return modr(floor(x), real(2)) > real(0.5) ? real(-1) : real(1); }
SHARED_FN real checkerWaveIntegral(real x) { return real(1) - abs(modr(x, real(2)) - real(1)); }
SHARED_FN real filteredCheckerWave(real x, real w) {
    if (!(w > PATTERN_MIN_FOOTPRINT)) {
        return checkerWave(x);
    }
    real h = real(0.5) * min(w, PATTERN_MAX_FOOTPRINT);
    return (checkerWaveIntegral(x + h) - checkerWaveIntegral(x - h)) / (real(2) * h);
}

// Grid lines: 1 within halfLine of an integer, else 0; its integral counts
// 2 halfLine per whole period of y = x + halfLine plus the part of the
// current one, min(fract(y), 2 halfLine).
SHARED_FN real gridLine(real x, real halfLine) { return abs(x - roundHalfUp(x)) < halfLine ? real(1) : real(0); }
SHARED_FN real gridLineIntegral(real x, real halfLine) {
    real y = x + halfLine;
    real whole = floor(y);
    return whole * (real(2) * halfLine) + min(y - whole, real(2) * halfLine);
}
SHARED_FN real filteredGridLine(real x, real halfLine, real w) {
    if (!(w > PATTERN_MIN_FOOTPRINT)) {
        return gridLine(x, halfLine);
    }
    real h = real(0.5) * min(w, PATTERN_MAX_FOOTPRINT);
    return saturate((gridLineIntegral(x + h, halfLine) - gridLineIntegral(x - h, halfLine)) / (real(2) * h));
}

// The share of the footprint (widths `footprint` in world units along x and
// z, centred at worldPoint) that the pattern paints in secondColor.
SHARED_FN real groundPatternCoverage(vec3 worldPoint, int pattern, real cellSize, real lineWidth, vec2 footprint) {
    real u = worldPoint.x / cellSize;
    real v = worldPoint.z / cellSize;
    real wu = footprint.x / cellSize;
    real wv = footprint.y / cellSize;
    if (pattern == GROUND_CHECKER) {
        // second on odd cells, where s(u) s(v) = -1
        return real(0.5) - real(0.5) * filteredCheckerWave(u, wu) * filteredCheckerWave(v, wv);
    }
    real halfLine = real(0.5) * lineWidth / cellSize;
    real onU = filteredGridLine(u, halfLine, wu);
    real onV = filteredGridLine(v, halfLine, wv);
    return real(1) - (real(1) - onU) * (real(1) - onV);
}

SHARED_FN Material groundMaterial(Material base, vec3 worldPoint, int pattern, real cellSize, real lineWidth,
                                  vec3 secondColor, vec2 footprint) {
    if (pattern == GROUND_PLAIN || !(cellSize > real(0))) {
        return base;
    }
    real coverage = groundPatternCoverage(worldPoint, pattern, cellSize, lineWidth, footprint);
    if (!(coverage > real(0))) {
        return base;
    }
    Material m = base;
    if (coverage >= real(1)) {
        m.ambient = secondColor;
        m.diffuse = secondColor;
    } else {
        m.ambient = lerp3s(base.ambient, secondColor, coverage);
        m.diffuse = lerp3s(base.diffuse, secondColor, coverage);
    }
    return m;
}
