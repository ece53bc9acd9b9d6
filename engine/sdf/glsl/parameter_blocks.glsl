// The parameter buffer's blocks: the scene-wide ones at fixed slots (trace
// settings, camera, MAX_LIGHTS lights), then the materials (their packer and
// unpacker are in material.glsl) and the instructions' parameters. The structs
// of the scene-wide blocks are declared here, beside their layout. Each block has one unpacker, read by both backends,
// and one packer, with which the compiler writes it (in double precision); a
// test checks that each undoes the other and that every struct's constructor
// calls pass every member, so a field cannot be missing from one layer.

struct Light {
    vec3 direction;  // unit, towards the light
    vec3 color;      // S_i
    real softness;   // k
};

// The environment map (environment.glsl): its images have side N = 2^n and
// `levels` = n + 1 mip levels each, from texel 0 of the texel buffer on.
struct EnvironmentMap {
    int kind;        // ENVIRONMENT_*
    int side;        // N
    int levels;
    real intensity;  // multiplies the images' radiance
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
    real exposure;           // multiplies the final linear colour
    vec3 ambientLight;       // L_A
    vec3 background;
    int maxDepth;            // bounces of the ray tree (ray_tree.glsl)
    real rayWeightCutoff;    // secondary rays lighter than this in every channel are dropped
    int groundPlane;         // 1 when the march takes the ground plane along the ray (tracer.glsl's groundAhead)
    real groundHeight;       // the ground's height in march coordinates (the eye's subtracted)
    int boundsUse;           // BOUNDS_* bits: what the tracer takes from the sphere below, in which
                             // every surface but the ground lies (0 when it knows none)
    vec3 boundsCenter;       // march coordinates (tracer.glsl's shadowRayClear, emptyMarchAhead)
    real boundsRadius;
};

// What the tracer takes from the scene's bounding sphere (tracing "bounded"
// sets them, the last for a ground without a bump map; tests turn one off
// to compare with the whole rays)
const int BOUNDS_END_SHADOW_RAYS = 1;  // shadowRayClear
const int BOUNDS_SKIP_MARCH = 2;       // emptyMarchAhead
const int BOUNDS_FLAT_GROUND = 4;      // onlyGroundWithin

const int MAX_LIGHTS = 8;
const int TRACE_SLOT = 0;
const int TRACE_SLOTS = 7;
const int CAMERA_SLOT = 7;      // TRACE_SLOT + TRACE_SLOTS
const int CAMERA_SLOTS = 4;
const int LIGHT_SLOT = 11;      // CAMERA_SLOT + CAMERA_SLOTS
const int LIGHT_SLOTS = 2;      // per light; unused lights are zero
const int ENVIRONMENT_SLOT = 27;  // LIGHT_SLOT + MAX_LIGHTS * LIGHT_SLOTS
const int ENVIRONMENT_SLOTS = 1;
const int MATERIAL_SLOT = 28;   // ENVIRONMENT_SLOT + ENVIRONMENT_SLOTS: the default material
const int MATERIAL_SLOTS = 6;

// ---- TraceSettings: (maxSteps, maxDistance, epsilon, epsilonPerDistance),
// (shadowMode, shadowSteps, aoSamples, aoDistance), (lightingModel, relaxation,
// lightCount, exposure), (ambientLight, maxDepth), (background, rayWeightCutoff),
// (groundPlane, groundHeight, boundsUse, unused), (boundsCenter, boundsRadius) ----
SHARED_FN TraceSettings traceSettingsFromSlots(vec4 q0, vec4 q1, vec4 q2, vec4 q3, vec4 q4, vec4 q5, vec4 q6) {
    return TraceSettings(int(q0.x), q0.y, q0.z, q0.w, int(q1.x), int(q1.y), int(q1.z), q1.w, int(q2.x), q2.y,
                         int(q2.z), q2.w, xyz(q3), xyz(q4), int(q3.w), q4.w, int(q5.x), q5.y, int(q5.z), xyz(q6),
                         q6.w);
}
SHARED_FN vec4 traceSettingsSlot(TraceSettings s, int i) {
    if (i == 0) {
        return vec4(real(s.maxSteps), s.maxDistance, s.epsilon, s.epsilonPerDistance);
    }
    if (i == 1) {
        return vec4(real(s.shadowMode), real(s.shadowSteps), real(s.aoSamples), s.aoDistance);
    }
    if (i == 2) {
        return vec4(real(s.lightingModel), s.relaxation, real(s.lightCount), s.exposure);
    }
    if (i == 3) {
        return vec4(s.ambientLight, real(s.maxDepth));
    }
    if (i == 4) {
        return vec4(s.background, s.rayWeightCutoff);
    }
    if (i == 5) {
        return vec4(real(s.groundPlane), s.groundHeight, real(s.boundsUse), real(0));
    }
    return vec4(s.boundsCenter, s.boundsRadius);
}

// ---- Camera: (origin, tanHalfFov), (forward, 0), (right, 0), (up, 0) ----
SHARED_FN Camera cameraFromSlots(vec4 q0, vec4 q1, vec4 q2, vec4 q3) {
    return Camera(xyz(q0), xyz(q1), xyz(q2), xyz(q3), q0.w);
}
SHARED_FN vec4 cameraSlot(Camera c, int i) {
    if (i == 0) {
        return vec4(c.origin, c.tanHalfFov);
    }
    if (i == 1) {
        return vec4(c.forward, real(0));
    }
    if (i == 2) {
        return vec4(c.right, real(0));
    }
    return vec4(c.up, real(0));
}

// ---- Light: (direction, softness), (color, 0) ----
SHARED_FN Light lightFromSlots(vec4 q0, vec4 q1) { return Light(xyz(q0), xyz(q1), q0.w); }
SHARED_FN vec4 lightSlot(Light l, int i) {
    if (i == 0) {
        return vec4(l.direction, l.softness);
    }
    return vec4(l.color, real(0));
}

// ---- EnvironmentMap: (kind, side, levels, intensity) ----
SHARED_FN EnvironmentMap environmentFromSlots(vec4 q0) { return EnvironmentMap(int(q0.x), int(q0.y), int(q0.z), q0.w); }
SHARED_FN vec4 environmentSlot(EnvironmentMap e, int i) {
    return vec4(real(e.kind), real(e.side), real(e.levels), e.intensity);
}
