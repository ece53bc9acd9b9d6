// Whitted ray tracing (lecture notes on realism, section 2: RayTracing and
// EvaluaMIL) without recursion, which GLSL does not have: the tree of rays is
// walked depth first through a small fixed stack of pending rays, each with
// its weight, the product of the k_ps M_PS and k_t M_T factors on its way from
// the eye. The driver (sample_driver.glsl) traces one ray at a time with the
// tracer's state machine; when a ray is done, rayTreeFinishRay adds its
// weighted colour and pushes its reflected and refracted rays.
//
// L = M_E + A_G + sum_i v_i S_i L_dir + k_ps M_PS L_in(p, r) + k_t M_T L_in(p, t)

// A ray of the tree's deepest level (max_depth bounces) pushes no children,
// so a depth-first walk holds at most one pending ray per level plus the
// pair just pushed: MAX_TRACE_DEPTH + 1 slots.
const int MAX_TRACE_DEPTH = 6;
// All rays of one sample share the driver's loop, whose back-edges llvmpipe
// caps at 65535 (docs/toolchain-notes.md): a tree whose worst case exceeds
// this many iterations stops there, keeping the rays it finished.
const int RAY_TREE_ITERATION_CAP = 65000;
// Secondary rays start where the field reads this many hit epsilons
// (surfaceOffset), on the side they travel into, so their first sample is
// clear of their surface.
const real RAY_START_OFFSET = real(3);

struct RayNode {
    vec3 origin;
    vec3 direction;
    vec3 weight;
    int depth;
    bool inside;
    real pathLength;
};

struct RayTree {
    vec3 color;    // sum of the finished rays' weighted colours
    vec3 weight;   // weight of the ray being traced
    int primarySteps;  // the primary ray's march: what the step statistics and heat image count
    int evaluations;   // of the field, by every ray finished so far
    bool primaryHit;
    real primaryT;
    int pending;   // rays on the stack: r0 .. r(pending - 1)
    RayNode r0;
    RayNode r1;
    RayNode r2;
    RayNode r3;
    RayNode r4;
    RayNode r5;
    RayNode r6;
};

SHARED_FN RayNode noRay() {
    return RayNode(vec3(real(0)), vec3(real(0), real(0), real(1)), vec3(real(0)), 0, false, real(0));
}

SHARED_FN RayTree rayTreeBegin() {
    RayNode none = noRay();
    return RayTree(vec3(real(0)), vec3(real(1)), 0, 0, false, real(0), 0, none, none, none, none, none, none, none);
}

SHARED_FN RayNode rayTreeTop(RayTree tree) {
    int i = tree.pending - 1;
    if (i == 0) {
        return tree.r0;
    }
    if (i == 1) {
        return tree.r1;
    }
    if (i == 2) {
        return tree.r2;
    }
    if (i == 3) {
        return tree.r3;
    }
    if (i == 4) {
        return tree.r4;
    }
    if (i == 5) {
        return tree.r5;
    }
    return tree.r6;
}

// The top ray becomes the one traced next.
SHARED_FN RayTree rayTreePop(RayTree tree) {
    tree.weight = rayTreeTop(tree).weight;
    tree.pending = tree.pending - 1;
    return tree;
}

SHARED_FN TraceState traceBeginNode(RayNode node) {
    return traceBeginRay(Ray(node.origin, node.direction), node.depth, node.inside, node.pathLength);
}

// What the ray's points are shifted by for their footprints
// (footprint_point.glsl): its point o + t d lies pathLength + t from the eye
// along the path, so it is measured at d (pathLength + t), the point plus
// d pathLength - o. None for a primary ray, whose points are measured as
// they are.
SHARED_FN vec4 footprintShiftOf(TraceState s) {
    if (s.depth == 0) {
        return vec4(real(0));
    }
    vec3 shift = s.rayDirection * s.pathLength - s.rayOrigin;
    return vec4(shift.x, shift.y, shift.z, real(1));
}

// A ray worth tracing: within the depth, and some channel at least the cutoff.
SHARED_FN bool rayWorthTracing(RayNode node, TraceSettings settings) {
    real heaviest = max(node.weight.x, max(node.weight.y, node.weight.z));
    return node.depth <= settings.maxDepth && heaviest > real(0) && heaviest >= settings.rayWeightCutoff;
}

SHARED_FN RayTree rayTreePush(RayTree tree, RayNode node, TraceSettings settings) {
    if (!rayWorthTracing(node, settings) || tree.pending > MAX_TRACE_DEPTH) {
        return tree;
    }
    int i = tree.pending;
    if (i == 0) {
        tree.r0 = node;
    } else if (i == 1) {
        tree.r1 = node;
    } else if (i == 2) {
        tree.r2 = node;
    } else if (i == 3) {
        tree.r3 = node;
    } else if (i == 4) {
        tree.r4 = node;
    } else if (i == 5) {
        tree.r5 = node;
    } else {
        tree.r6 = node;
    }
    tree.pending = i + 1;
    return tree;
}

// Mirror direction of `direction` about the unit normal n: r = 2 (n.v) n - v
// with v = -direction (the notes), n.v taken as at least 0.
SHARED_FN vec3 reflectDirection(vec3 direction, vec3 n) {
    real cosIncidence = max(-dot3(direction, n), real(0));
    return normalize3(direction + n * (real(2) * cosIncidence));
}

// Refraction by Snell's law n_i sin(theta_i) = n_t sin(theta_t), with
// ratio = n_i / n_t and n on the incoming side: t = ratio d + (ratio cos_i -
// cos_t) n. `total` when 1 < ratio^2 (1 - (i.n)^2), the notes' total
// internal reflection: then there is no refracted ray.
struct Refraction {
    vec3 direction;
    bool total;
    real cosTransmitted;
};

SHARED_FN Refraction refractDirection(vec3 direction, vec3 n, real ratio) {
    real cosIncidence = max(-dot3(direction, n), real(0));
    real k = real(1) - ratio * ratio * (real(1) - cosIncidence * cosIncidence);
    if (k < real(0)) {
        return Refraction(reflectDirection(direction, n), true, real(0));
    }
    real cosTransmitted = sqrt(k);
    vec3 t = direction * ratio + n * (ratio * cosIncidence - cosTransmitted);
    return Refraction(normalize3(t), false, cosTransmitted);
}

// The share of the transmitted fraction k_t that reflects instead: Schlick's
// approximation R0 + (1 - R0)(1 - cos)^5, R0 = ((n_i - n_t) / (n_i + n_t))^2,
// with the cosine on the side of the lower index; 1 under total internal
// reflection. The notes' model (fresnel 0) reflects nothing of k_t unless the
// reflection is total.
SHARED_FN real fresnelShare(Material m, real cosIncidence, Refraction refraction, real ratio) {
    if (refraction.total) {
        return real(1);
    }
    real r0 = (real(1) - m.ior) / (real(1) + m.ior);
    r0 = r0 * r0;
    real c = real(1) - (ratio > real(1) ? refraction.cosTransmitted : cosIncidence);
    real c2 = c * c;
    real schlick = r0 + (real(1) - r0) * (c2 * c2 * c);
    return m.fresnel * schlick;
}

// Adds the finished ray's colour with its weight, then (a hit within the
// depth) pushes its refracted and reflected rays, the reflected one on top.
// The reflected ray carries k_ps M_PS + F k_t M_T, the refracted one
// (1 - F) k_t M_T, F from fresnelShare. Rays leaving a solid use the ratio
// the other way (ior / 1).
SHARED_FN RayTree rayTreeFinishRay(RayTree tree, TraceState s, TraceSettings settings) {
    tree.color = tree.color + tree.weight * s.color;
    tree.evaluations = tree.evaluations + s.evaluations;
    if (s.depth == 0) {
        tree.primarySteps = s.steps;
        tree.primaryHit = s.hit;
        tree.primaryT = s.t;
    }
    Material m = s.material;
    if (!s.hit || s.depth >= settings.maxDepth || (m.reflectivity <= real(0) && m.transparency <= real(0))) {
        return tree;
    }
    vec3 n = s.shadingNormal;  // faces the ray: inside a solid the field is negated
    real ratio = s.inside ? m.ior : real(1) / m.ior;
    real cosIncidence = max(-dot3(s.rayDirection, n), real(0));
    Refraction refraction = refractDirection(s.rayDirection, n, ratio);
    real share = fresnelShare(m, cosIncidence, refraction, ratio);
    vec3 transmitted = m.transmissionColor * m.transparency;
    vec3 reflectedWeight = tree.weight * (m.reflectionColor * m.reflectivity + transmitted * share);
    vec3 refractedWeight = tree.weight * (transmitted * (real(1) - share));
    real offset = surfaceOffset(s, RAY_START_OFFSET);
    real path = s.pathLength + s.t;
    int depth = s.depth + 1;
    if (!refraction.total) {
        // off the surface along its own normal: a bumped one could point back into it
        RayNode through = RayNode(s.hitPoint - s.normal * offset, refraction.direction, refractedWeight, depth,
                                  !s.inside, path);
        tree = rayTreePush(tree, through, settings);
    }
    RayNode mirrored = RayNode(s.hitPoint + s.normal * offset, reflectDirection(s.rayDirection, n), reflectedWeight,
                               depth, s.inside, path);
    return rayTreePush(tree, mirrored, settings);
}

// What the sample returns: the tree's colour and evaluations, the primary ray's march and hit.
SHARED_FN TraceState rayTreeResult(RayTree tree, TraceState s) {
    s.color = tree.color;
    s.evaluations = tree.evaluations;
    s.steps = tree.primarySteps;
    s.hit = tree.primaryHit;
    s.t = tree.primaryT;
    return s;
}

// Inside a solid the ray marches on the negated field: the solid's surface
// is then a surface seen from outside, with its normal facing the ray, and
// its bumps are dents (a height along the outer normal, negated).
SHARED_FN Sample insideSample(Sample field) {
    Material m = field.material;
    m.bump = -m.bump;
    return Sample(-field.d, -field.step, m);
}

// Worst case of loop iterations for a sample's whole tree: every ray of a
// full binary tree of maxDepth levels at the tracer's bound, at most the cap.
SHARED_FN int rayTreeIterationBound(TraceSettings settings) {
    int rays = (1 << (clamp(settings.maxDepth, 0, MAX_TRACE_DEPTH) + 1)) - 1;
    return min(traceIterationBound(settings) * rays, RAY_TREE_ITERATION_CAP);
}
