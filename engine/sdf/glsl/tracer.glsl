// The per-sample tracer as a state machine (thesis, sections 2.1-2.2).
// A backend drives it with one loop and one evaluation of the scene per iteration:
//
//   TraceState s = traceBegin(ray);
//   while (s.phase != PHASE_DONE) {
//       Light light = lights[lightIndex(s)];
//       if (traceNeedsSample(s, settings)) field = map(tracePoint(s, light, settings));
//       s = traceAdvance(s, field, light, settings);
//   }
//
// so the GLSL backend has a single call site of map() (compile cost grows with call
// sites, see docs/toolchain-notes.md) and both backends share every formula.
// Phases: primary march, 4 tetrahedron normal samples, M ambient-occlusion
// samples, then per light either a shadow march or (shadows off) a direct shade.

const int PHASE_MARCH = 0;
const int PHASE_NORMAL = 1;
const int PHASE_AO = 2;
const int PHASE_SHADOW = 3;
const int PHASE_LIGHT = 4;
const int PHASE_DONE = 5;

const int SHADOW_NONE = 0;
const int SHADOW_HARD = 1;
const int SHADOW_SOFT = 2;
const int SHADOW_IMPROVED = 3;

const int LIGHTING_BLINN_PHONG = 0;
const int LIGHTING_PHONG = 1;

struct Light {
    vec3 direction;  // unit, towards the light
    vec3 color;      // S_i
    real softness;   // k
};

struct TraceSettings {
    int maxSteps;
    real maxDistance;
    real epsilon;            // absolute hit epsilon
    real epsilonPerDistance; // added footprint term: epsilon(t) = max(epsilon, epsilonPerDistance * t)
    int shadowMode;
    int shadowSteps;
    int aoSamples;           // M; 0 disables ambient occlusion
    real aoDistance;         // distance covered by the M samples along the normal
    int lightingModel;
    real relaxation;         // omega of over-relaxed primary steps, in [1, 2); 1 is plain sphere tracing
    int lightCount;
    vec3 ambientLight;       // L_A
    vec3 background;
};

struct TraceState {
    int phase;
    int counter;        // samples taken in the current phase
    int steps;          // primary-march evaluations
    bool hit;
    vec3 rayOrigin;
    vec3 rayDirection;
    real t;
    real lastDistance;  // the previous distance of the current march (0 before the first)
    real marchRadius;   // the primary march's last safe step (its unbounding sphere's radius)
    real marchStep;     // and the step it took from there: omega times marchRadius when relaxed
    bool relaxationOff; // a relaxed step overshot: plain steps for the rest of the ray
    vec3 hitPoint;
    real hitEpsilon;
    Material material;
    vec3 normalSum;
    vec3 normal;
    real occlusion;
    real occlusionWeight;
    real ao;
    int light;
    real shadowT;
    real shadowResult;
    vec3 color;
};

SHARED_FN TraceState traceBegin(Ray ray) {
    Material none = Material(vec3(real(0)), vec3(real(0)), vec3(real(0)), real(1), vec3(real(0)));
    return TraceState(PHASE_MARCH, 0, 0, false, ray.origin, ray.direction, real(0), real(0),
                      real(0), real(0), false, vec3(real(0)), real(0), none, vec3(real(0)), vec3(real(0)),
                      real(0), real(0), real(1), 0, real(0), real(1), vec3(real(0)));
}

SHARED_FN real hitEpsilonAt(TraceSettings settings, real t) {
    return max(settings.epsilon, settings.epsilonPerDistance * t);
}

// Vertices of the tetrahedron (1,-1,-1), (-1,-1,1), (-1,1,-1), (1,1,1).
SHARED_FN vec3 tetrahedronVertex(int index) {
    if (index == 0) {
        return vec3(real(1), real(-1), real(-1));
    }
    if (index == 1) {
        return vec3(real(-1), real(-1), real(1));
    }
    if (index == 2) {
        return vec3(real(-1), real(1), real(-1));
    }
    return vec3(real(1), real(1), real(1));
}

// Index into the light table for the current phase (always valid when lightCount > 0).
SHARED_FN int lightIndex(TraceState s) { return s.light; }

SHARED_FN bool traceNeedsSample(TraceState s) {
    return s.phase == PHASE_MARCH || s.phase == PHASE_NORMAL || s.phase == PHASE_AO ||
           s.phase == PHASE_SHADOW;
}

SHARED_FN vec3 shadowOrigin(TraceState s) {
    return s.hitPoint + s.normal * (real(2) * s.hitEpsilon);
}

SHARED_FN vec3 tracePoint(TraceState s, Light light, TraceSettings settings) {
    if (s.phase == PHASE_MARCH) {
        return s.rayOrigin + s.rayDirection * s.t;
    }
    if (s.phase == PHASE_NORMAL) {
        return s.hitPoint + tetrahedronVertex(s.counter) * s.hitEpsilon;
    }
    if (s.phase == PHASE_AO) {
        real h = real(s.counter + 1) / real(settings.aoSamples) * settings.aoDistance;
        return s.hitPoint + s.normal * h;
    }
    return shadowOrigin(s) + light.direction * s.shadowT;
}

// Blinn-Phong (thesis, Definition 2.4) or Phong reflected radiance for one light,
// before shadow and occlusion.
SHARED_FN vec3 reflectedRadiance(Material m, vec3 normal, vec3 toViewer, Light light, int model) {
    real nl = max(dot3(normal, light.direction), real(0));
    real specularBase = real(0);
    if (model == LIGHTING_PHONG) {
        vec3 reflected = normal * (real(2) * dot3(normal, light.direction)) - light.direction;
        specularBase = max(dot3(reflected, toViewer), real(0));
    } else {
        vec3 halfway = normalize3(light.direction + toViewer);
        specularBase = max(dot3(normal, halfway), real(0));
    }
    real specular = nl * safePow(specularBase, m.shininess);
    return light.color * (m.ambient + m.diffuse * nl + m.specular * specular);
}

SHARED_FN TraceState beginLight(TraceState s, TraceSettings settings) {
    s.shadowT = real(0);
    s.shadowResult = real(1);
    s.lastDistance = real(0);
    s.counter = 0;
    if (s.light >= settings.lightCount) {
        s.phase = PHASE_DONE;
    } else if (settings.shadowMode == SHADOW_NONE) {
        s.phase = PHASE_LIGHT;
    } else {
        s.phase = PHASE_SHADOW;
    }
    return s;
}

// L = L_A + L_E + sum_i S_i (R_A + NL R_D + NL R_E spec^alpha) shadow_i ao  (thesis, Alg. 14)
SHARED_FN TraceState beginShading(TraceState s, TraceSettings settings) {
    s.color = settings.ambientLight + s.material.emission;
    s.light = 0;
    return beginLight(s, settings);
}

SHARED_FN TraceState finishLight(TraceState s, Light light, TraceSettings settings, real shadow) {
    vec3 radiance = reflectedRadiance(s.material, s.normal, -s.rayDirection, light,
                                      settings.lightingModel);
    s.color = s.color + radiance * (shadow * s.ao);
    s.light = s.light + 1;
    return beginLight(s, settings);
}

SHARED_FN TraceState beginOcclusion(TraceState s, TraceSettings settings) {
    s.counter = 0;
    s.occlusion = real(0);
    s.occlusionWeight = real(0.5);
    s.ao = real(1);
    if (settings.aoSamples > 0) {
        s.phase = PHASE_AO;
        return s;
    }
    return beginShading(s, settings);
}

// Out of steps, a ray that grazes a surface (a floor towards the horizon) is
// still closing in on it: its distances shrink geometrically with ratio
// q = d_n / d_(n-1), so it would arrive after about step / (1 - q) more. It
// counts as a hit when that lands within max distance. (Primary rays at t,
// shadow rays at shadowT: both keep their previous distance in lastDistance.)
SHARED_FN bool convergesWithin(real t, real lastDistance, Sample field, TraceSettings settings) {
    if (!(lastDistance > real(0)) || !(field.d < lastDistance)) {
        return false;
    }
    real ratio = field.d / lastDistance;
    return t + field.step / (real(1) - ratio) <= settings.maxDistance;
}

// Out of distance or of steps: the background.
SHARED_FN TraceState endMarchIfSpent(TraceState s, TraceSettings settings) {
    if (s.t > settings.maxDistance || s.steps >= settings.maxSteps) {
        s.color = settings.background;
        s.phase = PHASE_DONE;
    }
    return s;
}

// Over-relaxed sphere tracing (Keinert et al. 2014): a step of omega times the
// safe step r leaves the previous point's unbounding sphere; as long as the new
// point's sphere overlaps it (r_prev + |r| >= step) the segment between them is
// clear of surfaces. When they do not overlap, the ray may have crossed one.
SHARED_FN bool relaxedStepOvershot(TraceState s, Sample field) {
    return s.marchStep > s.marchRadius && s.marchRadius + abs(field.step) < s.marchStep;
}

SHARED_FN TraceState advanceMarch(TraceState s, Sample field, TraceSettings settings) {
    s.steps = s.steps + 1;
    real epsilon = hitEpsilonAt(settings, s.t);
    if (relaxedStepOvershot(s, field)) {
        // back to the plain step from the previous point, which its sphere
        // keeps safe, and plain steps from now on (this evaluation is spent)
        s.t = s.t - s.marchStep + s.marchRadius;
        s.marchStep = s.marchRadius;
        s.relaxationOff = true;
        return endMarchIfSpent(s, settings);
    }
    if (field.d < -epsilon && field.step < real(0) && s.t > real(0) && s.steps < settings.maxSteps) {
        // A bound such as |F| / |grad F| can exceed the distance, so a step
        // can end inside the solid; a hit there would start its shadow rays
        // inside too (black spots). Back out by the safe step (negative
        // inside), which from inside never leaves the solid for an exact
        // field, until d >= -epsilon. (A displacement's step can have the
        // other sign than its distance: then the point is taken as it is.)
        s.t = max(s.t + field.step, real(0));
        s.lastDistance = field.d;
        s.marchRadius = real(0);
        s.marchStep = real(0);
        return s;
    }
    if (field.d < epsilon || (s.steps >= settings.maxSteps && convergesWithin(s.t, s.lastDistance, field, settings))) {
        s.hit = true;
        s.hitPoint = s.rayOrigin + s.rayDirection * s.t;
        s.hitEpsilon = epsilon;
        s.material = field.material;
        s.phase = PHASE_NORMAL;
        s.counter = 0;
        s.normalSum = vec3(real(0));
        return s;
    }
    // the safe step, and at least a fraction of epsilon so the march never stalls
    real radius = max(field.step, real(0.25) * epsilon);
    real step = s.relaxationOff ? radius : radius * settings.relaxation;
    if (s.t + step > settings.maxDistance) {
        step = radius;  // a relaxed step past max distance would end the ray unchecked
    }
    s.t = s.t + step;
    s.marchRadius = radius;
    s.marchStep = step;
    s.lastDistance = field.d;
    return endMarchIfSpent(s, settings);
}

SHARED_FN TraceState advanceNormal(TraceState s, Sample field, TraceSettings settings) {
    s.normalSum = s.normalSum + tetrahedronVertex(s.counter) * field.d;
    s.counter = s.counter + 1;
    if (s.counter < 4) {
        return s;
    }
    s.normal = normalize3(s.normalSum);
    return beginOcclusion(s, settings);
}

// Normal-sampled ambient occlusion (Evans 2006; thesis, Algorithm 15):
// ao = 1 - sum_i 2^-i (h_i - d_i) / D with h_i = i D / M.
SHARED_FN TraceState advanceOcclusion(TraceState s, Sample field, TraceSettings settings) {
    real h = real(s.counter + 1) / real(settings.aoSamples) * settings.aoDistance;
    s.occlusion = s.occlusion + s.occlusionWeight * (h - field.d);
    s.occlusionWeight = s.occlusionWeight * real(0.5);
    s.counter = s.counter + 1;
    if (s.counter < settings.aoSamples) {
        return s;
    }
    s.ao = saturate(real(1) - s.occlusion / settings.aoDistance);
    return beginShading(s, settings);
}

// Shadow rays (thesis, Algorithms 11-13): hard, soft res = min(res, k h / t), and the
// improved variant that lets the ray penetrate to res = -1 and remaps with smoothstep.
SHARED_FN TraceState advanceShadow(TraceState s, Sample field, Light light, TraceSettings settings) {
    s.counter = s.counter + 1;
    real d = field.d;
    bool exhausted = s.counter >= settings.shadowSteps;
    if (settings.shadowMode == SHADOW_IMPROVED) {
        if (s.shadowT > real(0)) {
            s.shadowResult = min(s.shadowResult, light.softness * d / s.shadowT);
        }
        s.shadowT = s.shadowT + max(abs(field.step), s.hitEpsilon);
        if (s.shadowResult < real(-1) || s.shadowT > settings.maxDistance || exhausted) {
            real clamped = max(s.shadowResult, real(-1));
            return finishLight(s, light, settings, smoothstepr(real(-1), real(1), clamped));
        }
        return s;
    }
    // out of steps while still closing in on an occluder: blocked, as for
    // primary rays (counting it lit let light leak into grazing shadows)
    if (d < s.hitEpsilon || (exhausted && convergesWithin(s.shadowT, s.lastDistance, field, settings))) {
        return finishLight(s, light, settings, real(0));
    }
    if (settings.shadowMode == SHADOW_SOFT && s.shadowT > real(0)) {
        s.shadowResult = min(s.shadowResult, light.softness * d / s.shadowT);
    }
    s.shadowT = s.shadowT + max(field.step, real(0.25) * s.hitEpsilon);
    s.lastDistance = d;
    if (s.shadowT > settings.maxDistance || exhausted) {
        return finishLight(s, light, settings, saturate(s.shadowResult));
    }
    return s;
}

SHARED_FN TraceState traceAdvance(TraceState s, Sample field, Light light, TraceSettings settings) {
    if (s.phase == PHASE_MARCH) {
        return advanceMarch(s, field, settings);
    }
    if (s.phase == PHASE_NORMAL) {
        return advanceNormal(s, field, settings);
    }
    if (s.phase == PHASE_AO) {
        return advanceOcclusion(s, field, settings);
    }
    if (s.phase == PHASE_SHADOW) {
        return advanceShadow(s, field, light, settings);
    }
    if (s.phase == PHASE_LIGHT) {
        return finishLight(s, light, settings, real(1));
    }
    return s;
}

// Worst case of loop iterations for one sample: the GLSL backend checks it against
// llvmpipe's loop limiter.
SHARED_FN int traceIterationBound(TraceSettings settings) {
    return settings.maxSteps + 4 + settings.aoSamples + settings.lightCount * (settings.shadowSteps + 1) + 1;
}
