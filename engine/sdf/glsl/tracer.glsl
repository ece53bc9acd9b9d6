// The per-sample tracer as a state machine (thesis, sections 2.1-2.2).
// sample_driver.glsl drives it, the same code in both backends: one loop, one
// evaluation of the scene per iteration, at most traceIterationBound iterations.
// Phases: primary march, 4 tetrahedron normal samples, the hit's material
// (one sample, five with an image bump map), M ambient-occlusion samples,
// then per light either a shadow march or (shadows off) a direct shade.

const int PHASE_MARCH = 0;
const int PHASE_NORMAL = 1;
const int PHASE_AO = 2;
const int PHASE_SHADOW = 3;
const int PHASE_LIGHT = 4;  // the light's shadow is decided: none taken, or a shadow ray no sample can change
const int PHASE_DONE = 5;
const int PHASE_LEAVE = 6;  // a primary ray that starts on a surface or inside a solid steps out of it
const int PHASE_ENTER = 7;  // a primary ray confirms a hit on a thin feature by entering it
const int PHASE_MATERIAL = 8;  // the hit's material, its image textures filtered by the normal's slant

const int SHADOW_NONE = 0;
const int SHADOW_HARD = 1;
const int SHADOW_SOFT = 2;
const int SHADOW_IMPROVED = 3;

const int LIGHTING_BLINN_PHONG = 0;
const int LIGHTING_PHONG = 1;

struct TraceState {
    int phase;
    int counter;        // samples taken in the current phase
    int steps;          // primary-march evaluations
    int evaluations;    // all evaluations of the field: march, normal, material, AO and shadow samples
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
    vec3 bumpSum;       // the normal's samples of the bump height, weighted alike
    vec3 normal;        // the surface's: offsets, shadows and AO start from it
    vec3 shadingNormal; // the normal with the bump map's perturbation: lighting and secondary rays
    real offsetScale;   // 1 over the field's slope across the surface (finishNormal): surfaceOffset, AO
    real occlusion;     // (in the normal phase: the hit's own distance)
    real occlusionWeight;
    real ao;
    int light;
    real shadowT;
    real shadowResult;
    real shadowBudget;  // shadow steps spent, each weighted by how fast the field lets the ray advance
    real shadowLastStep; // the shadow ray's previous step (0 before the first)
    vec3 shadowThrough; // improved shadows: what the transparent occluders met let through
    vec3 color;
    int depth;          // bounces before this ray: 0 for a primary ray (ray_tree.glsl)
    bool inside;        // the ray travels inside a solid: it marches on the negated field
    real pathLength;    // distance from the eye to this ray's origin: footprints (epsilon, textures)
    real enterSlope;    // PHASE_ENTER: the steepest rate of change of the field along the ray so far
    int materialSamples; // evaluations of PHASE_MATERIAL per hit (set by the driver): 1 for the hit's
                         // material, 5 with an image bump map (four around the hit first)
    real pixelAngle;    // a pixel's width per unit of distance (set by the driver): the bump samples' spacing
};

// A ray of the tree `depth` bounces from the eye, starting pathLength from it.
SHARED_FN TraceState traceBeginRay(Ray ray, int depth, bool inside, real pathLength) {
    Material none = noMaterial();
    return TraceState(PHASE_MARCH, 0, 0, 0, false, ray.origin, ray.direction, real(0), real(0),
                      real(0), real(0), false, vec3(real(0)), real(0), none, vec3(real(0)), vec3(real(0)),
                      vec3(real(0)), vec3(real(0)), real(1), real(0), real(0), real(1), 0, real(0), real(1), real(0),
                      real(0), vec3(real(1)), vec3(real(0)), depth, inside, pathLength, real(0), 0, real(0));
}

SHARED_FN TraceState traceBegin(Ray ray) { return traceBeginRay(ray, 0, false, real(0)); }

// The smallest step out of a surface the eye sits on, as a fraction of the
// max distance (a rasterizer's near plane at a near/far ratio of 1/1000): at
// t = 0 the pixel epsilon is 0, and a ray whose field is 0 there would never
// move. Smaller, a ray leaving a floor at a grazing angle crawls away from it
// in steps that grow by 1 + sin(angle) and ran out before reaching anything.
const real LEAVE_MIN_STEP = real(1e-3);
// How deep, as a fraction of the hit epsilon, a ray must get into a feature
// thinner than epsilon for it to count (PHASE_ENTER): slivers thinner than
// about three times this, a flush cutter's zero-thickness face among them, are not
// surfaces. Float noise on a flush face is far below it.
const real ENTER_DEPTH = real(0.015625);
// How far, as a fraction of the hit epsilon, the normal's probe goes through
// the surface: inside any surface whose radius of curvature exceeds epsilon.
const real NORMAL_PROBE = real(0.5);
// The least slope across a surface offsets believe (surfaceOffset): where the
// tetrahedron's samples straddle an edge or a V their sum is short, and an
// offset grown without bound there would step over nearby surfaces.
const real SURFACE_SLOPE_FLOOR = real(0.25);
// A shadow ray takes at most this many samples, however slowly its field
// steps (8 lights x 4097 stays well under llvmpipe's 65535 back-edges).
const int SHADOW_SAMPLE_CAP = 4096;

SHARED_FN real hitEpsilonAt(TraceSettings settings, real t) {
    return max(settings.epsilon, settings.epsilonPerDistance * t);
}

// The epsilon at the ray's current point, its footprint measured along the
// whole path from the eye (a primary ray's pathLength is 0).
SHARED_FN real rayEpsilon(TraceState s, TraceSettings settings) {
    return hitEpsilonAt(settings, s.pathLength + s.t);
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
           s.phase == PHASE_SHADOW || s.phase == PHASE_LEAVE || s.phase == PHASE_ENTER || s.phase == PHASE_MATERIAL;
}

// The primary ray's first sample, at the eye: where the march learns whether
// the eye starts inside a solid or inside glass. (A march that skipped empty
// space from the eye, skipEmptyMarch, has taken no step but is past it.)
SHARED_FN bool atPrimaryRayStart(TraceState s) {
    return s.steps == 0 && s.depth == 0 && s.t == real(0);
}

// What an evaluation reads of the material it returns, as bits. Only the
// material phase's material is shaded: every hit takes one evaluation there,
// at the hit, so the march's own material is never used. Other phases read
// one field each: shadows the transparency (glass tints them), the march's
// first sample too (the eye inside glass), the normal's samples the
// procedural bump height; AO and the rest read none. A backend may leave the
// materials out of an evaluation whose fields are 0 everywhere in the scene
// (Program::materialReads, cpu/interpreter.inl), and gets the same floats.
const int MATERIAL_READS_NONE = 0;
const int MATERIAL_READS_SHADING = 1;  // the whole material
const int MATERIAL_READS_TRANSPARENCY = 2;
const int MATERIAL_READS_BUMP = 4;
SHARED_FN int traceMaterialReads(TraceState s) {
    if (s.phase == PHASE_MATERIAL) {
        return MATERIAL_READS_SHADING;
    }
    if (s.phase == PHASE_SHADOW || (s.phase == PHASE_MARCH && atPrimaryRayStart(s))) {
        return MATERIAL_READS_TRANSPARENCY;
    }
    if (s.phase == PHASE_NORMAL) {
        return MATERIAL_READS_BUMP;
    }
    return MATERIAL_READS_NONE;
}

// Whether a scene whose evaluations read `sceneReads` (Program::materialReads)
// can take its material phase's evaluations apart from the others
// (sample_driver.glsl): then no other evaluation reads its materials.
SHARED_FN bool materialPhaseApart(int sceneReads) { return sceneReads == MATERIAL_READS_SHADING; }

// Image textures take their mip level from the footprint of a pixel across
// the ray (texture_lookup.glsl); on a surface seen at a slant the footprint
// is longer along it by 1 / cos, where a level that small would alias (moire
// towards the horizon). The material phase's evaluation widens the footprint
// by that factor (the larger of the two axes, as mipmapping hardware does),
// up to 16 (4 levels). Its material is the only one shaded: every other
// evaluation (march, normal, AO and shadow samples) reads distances, the
// bump height and the transparency, which textures do not change, so for
// those the factor is 0, "no colour needed", and the textures skip their
// lookups.
const real TEXTURE_MAX_STRETCH = real(16);
SHARED_FN real textureFootprintStretch(TraceState s) {
    if (s.phase != PHASE_MATERIAL) {
        return real(0);
    }
    real slant = abs(dot3(s.shadingNormal, s.rayDirection));
    return slant * TEXTURE_MAX_STRETCH > real(1) ? real(1) / slant : TEXTURE_MAX_STRETCH;
}

// Image bump maps (texture_lookup.glsl) are differentiated by the notes'
// central differences, with Delta about one texel of the level the lookups
// read: the material phase first evaluates the four tetrahedron vertices
// around the hit, a pixel's footprint apart, widened by the slant as the
// lookups' mip level is. (The normal's own samples, epsilon apart, would
// differentiate the bilinear interpolation between texels, which is
// discontinuous at every texel edge.)
const int HIT_MATERIAL_SAMPLE = 4;  // PHASE_MATERIAL's counter for the evaluation at the hit
SHARED_FN real bumpSpacing(TraceState s) {
    return s.pixelAngle * (s.pathLength + s.t) * textureFootprintStretch(s);
}

// How far off the surface a ray starts for the field to read `epsilons`
// hit epsilons there: a true distance reads the offset itself, a field that
// bounds it loosely (a formula divided by more than its Lipschitz constant)
// reads its slope times that, and a shadow ray started 2 epsilon off a
// surface of slope 0.4 read under epsilon and was called blocked.
SHARED_FN real surfaceOffset(TraceState s, real epsilons) {
    return epsilons * s.hitEpsilon * s.offsetScale;
}

SHARED_FN vec3 shadowOrigin(TraceState s) {
    return s.hitPoint + s.normal * surfaceOffset(s, real(2));
}

SHARED_FN vec3 tracePoint(TraceState s, Light light, TraceSettings settings) {
    if (s.phase == PHASE_MARCH || s.phase == PHASE_LEAVE || s.phase == PHASE_ENTER) {
        return s.rayOrigin + s.rayDirection * s.t;
    }
    if (s.phase == PHASE_MATERIAL && s.counter < HIT_MATERIAL_SAMPLE) {
        return s.hitPoint + tetrahedronVertex(s.counter) * bumpSpacing(s);
    }
    if (s.phase == PHASE_MATERIAL) {
        return s.hitPoint;
    }
    if (s.phase == PHASE_NORMAL && s.counter == 4) {
        return s.hitPoint - normalize3(s.normalSum) * (max(s.occlusion, real(0)) + NORMAL_PROBE * s.hitEpsilon);
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
    s.shadowBudget = real(0);
    s.shadowLastStep = real(0);
    s.shadowThrough = vec3(real(1));
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
    s.color = settings.ambientLight + s.material.emission * s.material.emissionStrength;
    s.light = 0;
    return beginLight(s, settings);
}

// `shadow` per channel: a transparent occluder tints the light it lets through.
SHARED_FN TraceState finishLight(TraceState s, Light light, TraceSettings settings, vec3 shadow) {
    vec3 radiance = reflectedRadiance(s.material, s.shadingNormal, -s.rayDirection, light,
                                      settings.lightingModel);
    s.color = s.color + radiance * (shadow * s.ao);
    s.light = s.light + 1;
    return beginLight(s, settings);
}

// How far, as a multiple of the hit epsilon, the normal's samples reach from
// the hit: the tetrahedron's vertices sqrt(3) away, the probe at most
// 1 + NORMAL_PROBE (advanceNormal).
const real NORMAL_REACH = real(2);

// Whether the field within `reach` of the hit is the ground plane's alone
// (BOUNDS_FLAT_GROUND): the hit lies farther than twice that plus its
// height above the plane (under epsilon, or more for a ray out of steps)
// from the sphere settings.boundsCenter, boundsRadius, which holds every
// other surface. Each point within reach is then farther from them than
// it is above the plane, so an exact field's union reads the plane's
// y - groundHeight there. (A field that bounds its distance loosely can
// read less near the floor, and its samples would have darkened the
// floor's occlusion; the plane is what is there.)
SHARED_FN bool onlyGroundWithin(TraceState s, TraceSettings settings, real reach) {
    if ((settings.boundsUse & BOUNDS_FLAT_GROUND) == 0 || s.inside) {
        return false;
    }
    vec3 v = s.hitPoint - settings.boundsCenter;
    real height = max(s.hitEpsilon, heightAboveGround(s.hitPoint, settings.groundHeight));
    real r = settings.boundsRadius + real(2) * reach + height;
    return dot3(v, v) > r * r;
}

SHARED_FN TraceState beginOcclusion(TraceState s, TraceSettings settings) {
    s.counter = 0;
    s.occlusion = real(0);
    s.occlusionWeight = real(0.5);
    s.ao = real(1);
    if (s.inside) {
        // the far side of a solid, seen from within: its lights are outside,
        // so it has no local illumination, only what its secondary rays bring
        s.color = vec3(real(0));
        s.phase = PHASE_DONE;
        return s;
    }
    // A floor with only the ground within reach (onlyGroundWithin) takes no
    // samples: along the plane's normal (beginNormal) they would read d + h_i
    // against h_i, no occlusion where the hit is on or above the plane.
    real aoReach = max(settings.aoDistance, NORMAL_REACH * s.hitEpsilon);
    if (settings.aoSamples > 0 && !onlyGroundWithin(s, settings, aoReach)) {
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

// The ground plane (settings.groundPlane: a ground, and the scene's
// tracing "bounded") is the one surface whose distance
// along a ray is known exactly: a ray above it heading down meets it after
// h / -dir.y, one heading up never does. Its instruction gives no step above
// the plane (instGround's GROUND_CLEAR_STEP) and the march steps by the least
// of the other surfaces' safe step and this: rays over an open floor reach it
// in a step or two instead of closing in on it geometrically (a ray of slope
// s shortens its height by the factor 1 - s a step), and rays towards the sky
// are not held back by the floor below them. Inside a solid the ray marches
// on the negated field, where the plane is no surface ahead.
SHARED_FN real groundAhead(TraceState s, TraceSettings settings) {
    if (settings.groundPlane == 0 || s.inside) {
        return GROUND_CLEAR_STEP;
    }
    real h = heightAboveGround(s.rayOrigin + s.rayDirection * s.t, settings.groundHeight);
    if (!(h > real(0))) {
        return h;
    }
    return s.rayDirection.y < real(0) ? h / -s.rayDirection.y : GROUND_CLEAR_STEP;
}

// The field's safe step with the ground plane's put back for the phases other
// than the march, which takes it along the ray (groundAhead): the plane's
// distance, as for any surface. The driver applies it to every evaluation at
// p, before a ray inside a solid negates the field.
SHARED_FN Sample withGroundStep(TraceState s, vec3 p, Sample field, TraceSettings settings) {
    if (settings.groundPlane == 0 || s.phase == PHASE_MARCH) {
        return field;
    }
    return Sample(field.d, min(field.step, heightAboveGround(p, settings.groundHeight)), field.material);
}

// The notes' bump mapping (1.2): with tangents t_u, t_v and the height's
// derivatives d_u, d_v along them, n' = normalize((t_u + d_u n) x (t_v + d_v n))
// = normalize(n - d_u t_u - d_v t_v), n minus the height's gradient g in the
// tangent plane. The four tetrahedron samples sum to about 4 epsilon g, as
// they do for the field's gradient. Without a bump map (g = 0) the normal is
// kept bit for bit.
SHARED_FN vec3 bumpedNormal(vec3 n, vec3 bumpSum, real epsilon) {
    if (!(dot3(bumpSum, bumpSum) > real(0))) {
        return n;
    }
    vec3 g = bumpSum / (real(4) * epsilon);
    return normalize3(n - (g - n * dot3(g, n)));
}

// The normal from the samples' sum, then the material phase.
SHARED_FN TraceState beginMaterial(TraceState s) {
    s.normal = normalize3(s.normalSum);
    // The samples sum to about 4 epsilon grad d (advanceNormal). A field
    // steeper than the distance keeps the offsets as they are: they are
    // already clear of the surface, and a shorter one is not. (At epsilon 0,
    // the eye on a surface in pixel mode, there is nothing to scale.)
    real unitSlopeSum = real(4) * s.hitEpsilon;
    real sum = length3(s.normalSum);
    s.offsetScale = sum >= unitSlopeSum ? real(1) : unitSlopeSum / max(sum, unitSlopeSum * SURFACE_SLOPE_FLOOR);
    // with an image bump map every bump map is differentiated over the
    // material phase's wider samples (advanceMaterial), the procedural ones too
    s.shadingNormal = s.materialSamples > 1 ? s.normal : bumpedNormal(s.normal, s.bumpSum, s.hitEpsilon);
    s.phase = PHASE_MATERIAL;
    s.counter = HIT_MATERIAL_SAMPLE + 1 - s.materialSamples;
    s.bumpSum = vec3(real(0));
    return s;
}

// A hit's normal phase. A floor with only the ground within its samples'
// reach (onlyGroundWithin) takes what they would give without taking them:
// the four samples y_i - groundHeight sum to 4 epsilon (0, 1, 0) (the
// tetrahedron's vertices sum to 0 and their y's squares to 4), the normal
// (0, 1, 0) at unit slope, and the lower two (or the probe) are inside: no
// thin feature. A floor far from the scene's objects costs no normal or
// occlusion samples (beginOcclusion). (The compiler sets the bit only for a
// ground without a bump map, whose normal samples would also sum the map's
// heights.)
SHARED_FN TraceState beginNormal(TraceState s, Sample field, real epsilon, TraceSettings settings) {
    s.hit = true;
    s.hitPoint = s.rayOrigin + s.rayDirection * s.t;
    s.hitEpsilon = epsilon;
    s.phase = PHASE_NORMAL;
    s.counter = 0;
    s.normalSum = vec3(real(0));
    s.bumpSum = vec3(real(0));
    s.lastDistance = field.d;  // the least distance at and around the hit: advanceNormal reads it
    s.occlusion = field.d;
    if (onlyGroundWithin(s, settings, NORMAL_REACH * epsilon)) {
        s.normalSum = vec3(real(0), real(4) * epsilon, real(0));
        return beginMaterial(s);
    }
    return s;
}

// One step out of the solid (or off the surface) the eye starts in: by the
// safe step's size, which inside an exact field never leaves the solid, and
// at least epsilon so the ray crosses its surface.
SHARED_FN TraceState leaveStep(TraceState s, Sample field, TraceSettings settings) {
    real epsilon = rayEpsilon(s, settings);
    s.steps = s.steps + 1;
    s.t = s.t + max(abs(field.step), max(epsilon, LEAVE_MIN_STEP * settings.maxDistance));
    s.marchRadius = real(0);  // plain steps: no relaxed step to check
    s.marchStep = real(0);
    return endMarchIfSpent(s, settings);
}

// How far the march can go from its next point without a sample (tracing
// "bounded"; 0: not at all, or no farther than the margin below, where the
// march is already at the sphere). Every surface but the ground lies in the
// sphere settings.boundsCenter, boundsRadius, and a point farther than
// epsilon from every surface is no hit. From a point outside that sphere widened by the
// ray's largest epsilon (at max distance), above the ground by as much, the
// ray meets nothing before it enters the widened sphere or reaches the ground
// plane (groundAhead), whichever comes first; GROUND_CLEAR_STEP when it does
// neither. The entry, c / (-b + sqrt(r^2 - |v - b dir|^2)) for the unit ray
// direction every ray has, avoids the cancellation of -b - sqrt(b^2 - c) at
// grazing rays, and is taken one margin early. Outside the sphere an exact
// field steps towards the scene by the distance to its surfaces, so rays
// that pass the scene stop sampling once they leave it, rays that miss it
// take no sample at all, and floor rays land on the ground in one step. A
// field that bounds its distance loosely could read below epsilon out there;
// the march no longer asks it.
SHARED_FN real emptyMarchAhead(TraceState s, TraceSettings settings) {
    if (s.phase != PHASE_MARCH || s.inside || (settings.boundsUse & BOUNDS_SKIP_MARCH) == 0) {
        return real(0);
    }
    real margin = hitEpsilonAt(settings, s.pathLength + settings.maxDistance);
    vec3 p = s.rayOrigin + s.rayDirection * s.t;
    if (settings.groundPlane != 0 && !(heightAboveGround(p, settings.groundHeight) > margin)) {
        return real(0);
    }
    vec3 v = p - settings.boundsCenter;
    real r = settings.boundsRadius + margin;
    real c = dot3(v, v) - r * r;
    if (!(c > real(0))) {
        return real(0);
    }
    real b = dot3(v, s.rayDirection);
    vec3 across = v - s.rayDirection * b;  // from the centre to the ray's closest point
    real chord = r * r - dot3(across, across);
    real entry = GROUND_CLEAR_STEP;
    if (b < real(0) && chord >= real(0)) {
        entry = c / (safeSqrt(chord) - b) - margin;
    }
    // the ground, when ahead, is farther than the height checked above
    return entry > margin ? min(entry, groundAhead(s, settings)) : real(0);
}

// The driver asks before each evaluation: a march with empty space ahead
// (emptyMarchAhead) crosses it without an evaluation or a step of its
// budget, onto the ground plane or to the widened sphere's entry; a ray
// that meets neither within max distance ends on the background, and one
// whose ground lies past it takes one more sample at max distance, which
// decides as in advanceMarch.
SHARED_FN TraceState skipEmptyMarch(TraceState s, TraceSettings settings) {
    real ahead = emptyMarchAhead(s, settings);
    if (!(ahead > real(0))) {
        return s;
    }
    real plane = groundAhead(s, settings);
    bool beyond = !(s.t + ahead <= settings.maxDistance);
    s.marchRadius = real(0);  // no relaxed step to check, no previous distance
    s.marchStep = real(0);
    s.lastDistance = real(0);
    if (beyond && !(plane < GROUND_CLEAR_STEP)) {
        s.color = settings.background;
        s.phase = PHASE_DONE;
        return s;
    }
    s.t = beyond ? settings.maxDistance : s.t + ahead;
    return s;
}

SHARED_FN TraceState advanceMarch(TraceState s, Sample field, TraceSettings settings) {
    if (atPrimaryRayStart(s) && field.d < -rayEpsilon(s, settings) && field.material.transparency > real(0) &&
        settings.maxDepth > 0) {
        // The eye inside glass (a transparent solid; the ray tree is on, as
        // it is whenever a material transmits and max_depth > 0) looks out
        // through it: from the next sample on, the ray marches inside.
        s.inside = true;
        s.steps = 1;
        return s;
    }
    // the safe step along the ray, the ground plane's included (groundAhead)
    real ahead = groundAhead(s, settings);
    bool planeAhead = ahead < GROUND_CLEAR_STEP;  // the ground plane is met along the ray
    Sample stepped = planeAhead ? Sample(field.d, min(field.step, ahead), field.material) : field;
    if (atPrimaryRayStart(s) && field.d <= rayEpsilon(s, settings)) {
        // The eye is on a surface or inside a solid (a camera orbiting into
        // the floor, placed on an object): what is behind the eye's own
        // surface is seen, that surface is not. (A hit at t = 0 gave one flat
        // colour; with the pixel epsilon, 0 at t = 0, the ray never moved.)
        // Secondary rays start off their surface (ray_tree.glsl) and march on.
        s.phase = PHASE_LEAVE;
        return leaveStep(s, stepped, settings);
    }
    s.steps = s.steps + 1;
    real epsilon = rayEpsilon(s, settings);
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
    if (field.d < epsilon ||
        (s.steps >= settings.maxSteps && convergesWithin(s.t, s.lastDistance, stepped, settings))) {
        return beginNormal(s, field, epsilon, settings);
    }
    // the safe step, and at least a fraction of epsilon so the march never stalls
    real radius = max(stepped.step, real(0.25) * epsilon);
    real step = s.relaxationOff ? radius : radius * settings.relaxation;
    if (s.t + step > settings.maxDistance || (planeAhead && step >= ahead)) {
        // a relaxed step past max distance would end the ray unchecked; one
        // onto the ground plane would land on either side of it at random
        // and be taken for an overshoot half the time (a plain one lands on it)
        step = radius;
    }
    // the ground plane lies past max distance: one more sample at max distance
    // (exactly: t + (max - t) can round past it), which hits it when within
    // epsilon of it, as closing in on it step by step did (a ray ends past
    // max distance unchecked)
    bool lastSample =
        planeAhead && ahead <= field.step && s.t < settings.maxDistance && s.t + step > settings.maxDistance;
    if (lastSample) {
        step = settings.maxDistance - s.t;
    }
    s.t = lastSample ? settings.maxDistance : s.t + step;
    s.marchRadius = radius;
    s.marchStep = step;
    s.lastDistance = field.d;
    return endMarchIfSpent(s, settings);
}

// Until it is outside (d > epsilon): then it marches on from there.
SHARED_FN TraceState advanceLeave(TraceState s, Sample field, TraceSettings settings) {
    if (field.d > rayEpsilon(s, settings)) {
        s.phase = PHASE_MARCH;
        return advanceMarch(s, field, settings);
    }
    return leaveStep(s, field, settings);
}

// Around a hit on a feature thinner than epsilon the ray looks for the
// field's sign: a hit where d < -ENTER_DEPTH epsilon, or, once d > epsilon
// again, a sliver with nothing inside passed, and the march goes on.
SHARED_FN TraceState advanceEnter(TraceState s, Sample field, TraceSettings settings) {
    real epsilon = rayEpsilon(s, settings);
    real depth = ENTER_DEPTH * epsilon;
    if (field.d < -depth) {
        return beginNormal(s, field, epsilon, settings);
    }
    s.steps = s.steps + 1;
    if (s.marchStep > real(0)) {
        s.enterSlope = max(s.enterSlope, abs(field.d - s.lastDistance) / s.marchStep);
    }
    // A feature at least 3 depth thick, crossed where the field changes at
    // this rate along the ray, stays below -depth over at least
    // depth / slope: steps that long still find it, and a ray grazing a
    // sliver's plane (the field near 0 over a long stretch) crosses it in
    // about 2 / ENTER_DEPTH steps instead of running out of them.
    real step = max(field.step, depth / max(s.enterSlope, ENTER_DEPTH));
    s.t = s.t + step;
    s.lastDistance = field.d;
    s.marchRadius = real(0);  // plain steps: no relaxed step to check
    s.marchStep = step;       // the step the next slope is measured over
    if (field.d > epsilon) {
        s.phase = PHASE_MARCH;
        s.marchStep = real(0);
    }
    return endMarchIfSpent(s, settings);
}

// A hit none of whose samples is inside is on a feature thinner than
// epsilon: it counts only where the ray gets into it (PHASE_ENTER). A ray
// out of steps keeps its hit.
SHARED_FN TraceState finishNormal(TraceState s, TraceSettings settings) {
    bool thin = s.lastDistance >= -ENTER_DEPTH * s.hitEpsilon;
    if (thin && s.steps < settings.maxSteps) {
        s.hit = false;
        s.phase = PHASE_ENTER;
        s.steps = s.steps + s.counter;  // the normal's samples count against the budget that bounds the loop
        s.enterSlope = real(0);
        s.marchStep = real(0);  // no step yet to measure a slope over
        return endMarchIfSpent(s, settings);
    }
    return beginMaterial(s);
}

// The bump samples around the hit, then the hit's material with its image
// textures filtered for the slant.
SHARED_FN TraceState advanceMaterial(TraceState s, Sample field, TraceSettings settings) {
    if (s.counter < HIT_MATERIAL_SAMPLE) {
        s.bumpSum = s.bumpSum + tetrahedronVertex(s.counter) * field.material.bump;
        s.counter = s.counter + 1;
        return s;
    }
    s.material = field.material;
    if (s.materialSamples > 1) {
        s.shadingNormal = bumpedNormal(s.normal, s.bumpSum, bumpSpacing(s));
    }
    return beginOcclusion(s, settings);
}

SHARED_FN TraceState advanceNormal(TraceState s, Sample field, TraceSettings settings) {
    if (s.counter == 4) {
        // the probe through the surface (below)
        s.lastDistance = min(s.lastDistance, field.d);
        s.counter = 5;
        return finishNormal(s, settings);
    }
    s.normalSum = s.normalSum + tetrahedronVertex(s.counter) * field.d;
    s.bumpSum = s.bumpSum + tetrahedronVertex(s.counter) * field.material.bump;
    s.lastDistance = min(s.lastDistance, field.d);
    s.counter = s.counter + 1;
    if (s.counter < 4) {
        return s;
    }
    // At a surface the four samples sum to about 4 epsilon grad d, of length
    // 4 epsilon, and within epsilon of it some sample lies inside. Where the
    // field is V-shaped around the hit, |x| about a plane at the hit's
    // distance h, the sum is 2 epsilon to 4 h long, and no sample is inside:
    // a feature thinner than epsilon (a blade, a shell) or a sliver the field
    // only touches (a cutter flush with the face it cuts leaves one of zero
    // thickness, seen as a striped lid or a membrane). Such a hit counts only
    // where the field goes negative (PHASE_ENTER). The same V seen from
    // one side only (h near epsilon, as a ray grazing a sliver's plane first
    // gets within epsilon of it) is a linear field around the samples: then
    // one more sample, the probe, goes through the surface along the normal,
    // NORMAL_PROBE epsilon beyond it, and the hit counts only if the probe is
    // inside.
    real h = max(s.occlusion, real(0));
    bool vShaped = length3(s.normalSum) < real(2.5) * s.hitEpsilon + real(1.5) * h;
    if (!vShaped && s.lastDistance >= -ENTER_DEPTH * s.hitEpsilon) {
        return s;  // counter 4: the probe
    }
    return finishNormal(s, settings);
}

// Normal-sampled ambient occlusion (Evans 2006; thesis, Algorithm 15):
// ao = 1 - sum_i 2^-i (h_i - d_i) / D with h_i = i D / M. A field that
// bounds the distance loosely reads about its slope times h_i along an open
// normal, and a convex surface of slope 0.4 came out occluded to 0.76
// (M = 4): d_i is read in the surface's own scale, as its offsets are
// (surfaceOffset). That scale is the hit surface's: another surface near it
// (an exact floor by a loose stone) or a crease the normal's samples
// straddle reads farther than it is, so a scaled reading stops at h_i, where
// it makes no occlusion, rather than going on to cancel what the other
// samples found. (Unscaled readings are left as they are.)
SHARED_FN TraceState advanceOcclusion(TraceState s, Sample field, TraceSettings settings) {
    real h = real(s.counter + 1) / real(settings.aoSamples) * settings.aoDistance;
    real reading = min(field.d * s.offsetScale, max(field.d, h));
    s.occlusion = s.occlusion + s.occlusionWeight * (h - reading);
    s.occlusionWeight = s.occlusionWeight * real(0.5);
    s.counter = s.counter + 1;
    if (s.counter < settings.aoSamples) {
        return s;
    }
    s.ao = saturate(real(1) - s.occlusion / settings.aoDistance);
    return beginShading(s, settings);
}

// The penumbra estimate k h / t at the ray's closest approach to the occluder
// between the previous sample and this one (Quilez 2018): the empty spheres
// of radius lastDistance and h, their centres a step apart, meet a distance y
// before this sample, at a distance sqrt(h^2 - y^2) from the ray. Taking
// k h / t at the samples only made bands like wood grain in the lit side of
// a box with k ~ 8: where the samples fell relative to the occluder
// changed from pixel to pixel. The meeting circle counts only between the
// two samples (y < step), where the estimate runs continuously from this
// sample's (y = 0) to the previous one's (y = step): a ray moving away from
// a surface (h = lastDistance + step) has its spheres meet on the ray behind
// the previous sample, and counting that as a closest approach of 0 turned
// such rays dark at random (speckled penumbrae of slow-stepping fields, and
// a verdict a last bit could flip between the backends).
SHARED_FN real penumbraEstimate(TraceState s, real h, real k) {
    real estimate = k * h / s.shadowT;
    real last = s.lastDistance;
    real step = s.shadowLastStep;
    if (last > real(0) && h > real(0) && step > real(0)) {
        real y = (h * h - last * last + step * step) / (real(2) * step);
        if (y > real(0) && y < h && y < step && y < s.shadowT) {
            estimate = min(estimate, k * sqrt(h * h - y * y) / (s.shadowT - y));
        }
    }
    return estimate;
}

// What a shadow ray blocked by a surface of material m lets through: k_t M_T,
// at most 1 per channel (a simplification: the light is not refracted, the
// occluder is not marched through (improved shadows march on through it, but
// take the least of what each transparent occluder lets through, not their
// product), what lies behind it is not seen; an opaque occluder lets 0
// through, so no transparent one shadows more).
SHARED_FN vec3 occluderTransmission(Material m) {
    vec3 through = m.transmissionColor * m.transparency;
    return vec3(saturate(through.x), saturate(through.y), saturate(through.z));
}
SHARED_FN real occluderOpenness(Material m) {
    vec3 through = occluderTransmission(m);
    return max(through.x, max(through.y, through.z));
}

// What a shadow ray ended with lets through: the improved variant's
// remapped result (tinted by the transparent occluders it met), the others'
// result; 1 for a ray not taken (no shadows).
SHARED_FN vec3 shadowOutcome(TraceState s, TraceSettings settings) {
    if (settings.shadowMode == SHADOW_IMPROVED) {
        return s.shadowThrough * smoothstepr(real(-1), real(1), max(s.shadowResult, real(-1)));
    }
    return vec3(saturate(s.shadowResult));
}

// Whether a shadow ray's remaining samples can no longer change its outcome,
// so that it ends before taking them. Every surface but the ground lies in
// the sphere settings.boundsCenter, boundsRadius (BOUNDS_END_SHADOW_RAYS), so
// the points p + u dir of the ray from its next sample p = o + T dir on are at
// least |p + u dir - c| - R from them and (p + u dir).y - groundHeight from
// the ground. A sample lowers the result only where its distance reads below
// m (T + u), m = max(result, 0) / k (0 for hard shadows, which have no
// penumbra), and blocks or tints the light only within epsilon: when both
// distances stay above m (T + u) + epsilon for every u >= 0 (up to max
// distance for the ground, which is linear along the ray; for the sphere,
// squaring gives (1 - m^2) u^2 + 2 b u + c >= 0 with b and c below), none
// can. Shadow rays from an open floor towards a light above the scene take no
// sample at all, and rays that have passed their occluders stop sampling the
// empty space after them. What the whole ray would have read there and the
// distances do not say: a field that bounds distances loosely can read
// lower; soft shadows' estimate between samples (penumbraEstimate) reads
// down to 1/sqrt(2) of the distances (a light grazing the floor at slope
// about 1/k darkened the floor by its own plane); and a ray out of budget
// while its distance still falls was called blocked (convergesWithin). An
// ended ray keeps what the distances say instead.
// (boundsUse is set only with tracing "bounded", under which groundPlane
// says whether there is a ground.)
SHARED_FN bool shadowRayClear(TraceState s, Light light, TraceSettings settings) {
    if (s.phase != PHASE_SHADOW || (settings.boundsUse & BOUNDS_END_SHADOW_RAYS) == 0) {
        return false;
    }
    real slope = settings.shadowMode == SHADOW_HARD ? real(0) : max(s.shadowResult, real(0)) / light.softness;
    if (!(slope < real(1))) {
        return false;
    }
    vec3 p = shadowOrigin(s) + light.direction * s.shadowT;
    real margin = s.hitEpsilon + slope * s.shadowT;
    if (settings.groundPlane != 0) {
        real above = heightAboveGround(p, settings.groundHeight) - margin;
        real reach = max(settings.maxDistance - s.shadowT, real(0));
        if (!(above >= real(0)) || !(above + reach * (light.direction.y - slope) >= real(0))) {
            return false;
        }
    }
    vec3 v = p - settings.boundsCenter;
    real r = settings.boundsRadius + margin;
    real c = dot3(v, v) - r * r;
    if (!(c >= real(0))) {
        return false;
    }
    real b = dot3(v, light.direction) - r * slope;
    return b >= real(0) || b * b <= (real(1) - slope * slope) * c;
}

// The driver asks before each evaluation: a shadow ray that no sample can
// change finishes its light (PHASE_LIGHT, with what the ray found so far).
SHARED_FN TraceState skipClearShadowRay(TraceState s, Light light, TraceSettings settings) {
    if (shadowRayClear(s, light, settings)) {
        s.phase = PHASE_LIGHT;
    }
    return s;
}

// Shadow rays (thesis, Algorithms 11-13): hard, soft res = min(res, k h / t), and the
// improved variant that lets the ray penetrate to res = -1 and remaps with smoothstep.
// The budget counts each sample by the fraction of the distance its step covers,
// so a field that steps slowly (a displacement's step is about a tenth of its
// distance) gets as many steps' worth of progress as an exact one, up to
// SHADOW_SAMPLE_CAP samples: out of 96 samples there, its shadow rays were
// called blocked and its shadow came out too dark and too large.
SHARED_FN TraceState advanceShadow(TraceState s, Sample field, Light light, TraceSettings settings) {
    s.counter = s.counter + 1;
    real d = field.d;
    real pace = real(1);
    if (abs(d) > abs(field.step)) {
        pace = abs(field.step) / abs(d);
    }
    s.shadowBudget = s.shadowBudget + pace;
    bool exhausted = s.shadowBudget >= real(settings.shadowSteps) || s.counter >= SHADOW_SAMPLE_CAP;
    if (settings.shadowMode == SHADOW_IMPROVED) {
        if (field.material.transparency > real(0)) {
            // a transparent occluder does not enter the penumbra estimate
            // (it has no penumbra here): within epsilon of it or inside,
            // the light is tinted by what it lets through, k_t M_T
            if (d < s.hitEpsilon) {
                s.shadowThrough = min(s.shadowThrough, occluderTransmission(field.material));
            }
        } else if (s.shadowT > real(0)) {
            s.shadowResult = min(s.shadowResult, light.softness * d / s.shadowT);
        }
        s.shadowT = s.shadowT + max(abs(field.step), s.hitEpsilon);
        if (s.shadowResult < real(-1) || s.shadowT > settings.maxDistance || exhausted) {
            return finishLight(s, light, settings, shadowOutcome(s, settings));
        }
        return s;
    }
    // out of steps while still closing in on an occluder: blocked, as for
    // primary rays (counting it lit let light leak into grazing shadows)
    if (d < s.hitEpsilon || (exhausted && convergesWithin(s.shadowT, s.lastDistance, field, settings))) {
        return finishLight(s, light, settings, occluderTransmission(field.material));
    }
    if (settings.shadowMode == SHADOW_SOFT && s.shadowT > real(0)) {
        real estimate = penumbraEstimate(s, d, light.softness);
        if (field.material.transparency > real(0)) {
            // the penumbra of a transparent occluder only falls to what it lets through
            estimate = lerpr(estimate, real(1), occluderOpenness(field.material));
        }
        s.shadowResult = min(s.shadowResult, estimate);
    }
    s.shadowLastStep = max(field.step, real(0.25) * s.hitEpsilon);
    s.shadowT = s.shadowT + s.shadowLastStep;
    s.lastDistance = d;
    if (s.shadowT > settings.maxDistance || exhausted) {
        return finishLight(s, light, settings, shadowOutcome(s, settings));
    }
    return s;
}

SHARED_FN TraceState traceAdvance(TraceState s, Sample field, Light light, TraceSettings settings) {
    if (s.phase == PHASE_MARCH) {
        return advanceMarch(s, field, settings);
    }
    if (s.phase == PHASE_LEAVE) {
        return advanceLeave(s, field, settings);
    }
    if (s.phase == PHASE_ENTER) {
        return advanceEnter(s, field, settings);
    }
    if (s.phase == PHASE_NORMAL) {
        return advanceNormal(s, field, settings);
    }
    if (s.phase == PHASE_MATERIAL) {
        return advanceMaterial(s, field, settings);
    }
    if (s.phase == PHASE_AO) {
        return advanceOcclusion(s, field, settings);
    }
    if (s.phase == PHASE_SHADOW) {
        return advanceShadow(s, field, light, settings);
    }
    if (s.phase == PHASE_LIGHT) {
        return finishLight(s, light, settings, shadowOutcome(s, settings));
    }
    return s;
}

// Worst case of loop iterations for one sample: the GLSL backend checks it against
// llvmpipe's loop limiter. The march's steps (normal samples of a thin hit
// among them) stop at maxSteps, 5 over at most, then 5 normal samples and
// the material phase's five at most.
SHARED_FN int traceIterationBound(TraceSettings settings) {
    int shadowSamples = settings.shadowMode == SHADOW_NONE ? 0 : SHADOW_SAMPLE_CAP;
    return settings.maxSteps + 15 + settings.aoSamples + settings.lightCount * (shadowSamples + 1) + 1;
}
