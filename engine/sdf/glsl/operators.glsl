// Operators on distances and on points (thesis, section 1.3).
// Smooth booleans take a blend radius k in distance units; docs/scene-format.md
// gives the mapping from k to each variant's own parameter. Every smooth minimum
// also returns its blend weight: the partial derivative of the result with respect
// to the second operand, in [0, 1], used to mix the operands' materials.

struct Blend {
    real d;
    real w;
};

SHARED_FN Blend hardMin(real a, real b) {
    if (a <= b) {
        return Blend(a, real(0));
    }
    return Blend(b, real(1));
}

// Polynomial: min(a,b) - max(k-|a-b|,0)^n / (2n k^(n-1)), n in {2, 3}.
SHARED_FN Blend sminPolynomial(real a, real b, real k, real n) {
    if (!(k > real(0))) {
        return hardMin(a, b);
    }
    real h = max(k - abs(a - b), real(0)) / k;
    real hPowNMinus1 = n > real(2.5) ? h * h : h;
    real omega = hPowNMinus1 * h * k / (real(2) * n);
    real w = real(0.5) * hPowNMinus1;
    if (a <= b) {
        return Blend(a - omega, w);
    }
    return Blend(b - omega, real(1) - w);
}

// Exponential: -log2(2^(-sa) + 2^(-sb)) / s with sharpness s = 4 / k, written as
// min(a,b) - log2(1 + 2^(-s|a-b|)) / s so it never overflows.
SHARED_FN Blend sminExponential(real a, real b, real k) {
    if (!(k > real(0))) {
        return hardMin(a, b);
    }
    real sharpness = real(4) / k;
    real e = libraryExp2(-sharpness * abs(a - b));
    real d = min(a, b) - libraryLog2(real(1) + e) / sharpness;
    real wOfLarger = e / (real(1) + e);
    if (a <= b) {
        return Blend(d, wOfLarger);
    }
    return Blend(d, real(1) - wOfLarger);
}

// Power: ((a^s b^s) / (a^s + b^s))^(1/s) with s = 1 / k, written as
// m * (1 + (m/M)^s)^(-1/s) for m = min, M = max. Defined for a, b > 0 only:
// where either operand is <= 0 it is the hard minimum. The weight of b is
// d(result)/db = (result / b)^(s + 1).
SHARED_FN Blend sminPower(real a, real b, real k) {
    if (!(k > real(0)) || a <= real(0) || b <= real(0)) {
        return hardMin(a, b);
    }
    real s = real(1) / k;
    real m = min(a, b);
    real ratioPow = libraryExp2(s * libraryLog2(m / max(a, b)));
    real d = m * libraryExp2(-libraryLog2(real(1) + ratioPow) / s);
    return Blend(d, libraryExp2((s + real(1)) * libraryLog2(d / b)));
}

// Root: (a + b - sqrt((a-b)^2 + c)) / 2 with c = k^2 / 4, written as
// min(a,b) - c / (2 (root + |a-b|)) with root = sqrt((a-b)^2 + c): a + b - root
// cancels completely when one operand is huge (an empty group's 1e10 against
// a surface at 1 gave 0 in float, and every ray stalled). The weight of the
// larger operand, (1 - |a-b| / root) / 2, likewise as c / (2 root (root + |a-b|)).
SHARED_FN Blend sminRoot(real a, real b, real k) {
    real c = k * k * real(0.25);
    real gap = abs(a - b);
    real root = sqrt(gap * gap + c);
    if (!(root > real(0))) {
        return hardMin(a, b);
    }
    real sum = root + gap;
    real d = min(a, b) - real(0.5) * c / sum;
    real wOfLarger = real(0.5) * c / (root * sum);
    if (a <= b) {
        return Blend(d, wOfLarger);
    }
    return Blend(d, real(1) - wOfLarger);
}

// Variant codes, fixed numbers shared with the compiler (engine/program/opcodes.h).
const int SMOOTH_POLYNOMIAL = 0;
const int SMOOTH_EXPONENTIAL = 1;
const int SMOOTH_POWER = 2;
const int SMOOTH_ROOT = 3;

// A shader holds only the variants its scene uses: the GL generator defines
// SMOOTH_VARIANTS_OF_SCENE and SMOOTH_USES_<NAME> for each variant used
// (gl/shader_generator.cpp), because Mesa inlines every branch of this
// dispatch at every call before it folds the constant variant, and the
// exponential and power branches' exp2 and log2 made each smooth boolean cost
// about 50 ms of compile time (docs/toolchain-notes.md). C++ compiles them all.
SHARED_FN Blend smoothMin(int variant, real a, real b, real k, real n) {
#if !defined(SMOOTH_VARIANTS_OF_SCENE) || defined(SMOOTH_USES_EXPONENTIAL)
    if (variant == SMOOTH_EXPONENTIAL) {
        return sminExponential(a, b, k);
    }
#endif
#if !defined(SMOOTH_VARIANTS_OF_SCENE) || defined(SMOOTH_USES_POWER)
    if (variant == SMOOTH_POWER) {
        return sminPower(a, b, k);
    }
#endif
#if !defined(SMOOTH_VARIANTS_OF_SCENE) || defined(SMOOTH_USES_ROOT)
    if (variant == SMOOTH_ROOT) {
        return sminRoot(a, b, k);
    }
#endif
    return sminPolynomial(a, b, k, n);
}

// smax(a, b) = -smin(-a, -b); the weight of b carries over unchanged.
SHARED_FN Blend smoothMax(int variant, real a, real b, real k, real n) {
    Blend m = smoothMin(variant, -a, -b, k, n);
    return Blend(-m.d, m.w);
}

SHARED_FN Blend hardMax(real a, real b) {
    if (a >= b) {
        return Blend(a, real(0));
    }
    return Blend(b, real(1));
}

// ---- point operators: map a point to the child's frame ----

SHARED_FN vec3 opTranslate(vec3 p, vec3 offset) { return p + offset; }

// rows of the inverse rotation, computed by the host
SHARED_FN vec3 opRotate(vec3 p, vec3 row0, vec3 row1, vec3 row2) {
    return vec3(dot3(row0, p), dot3(row1, p), dot3(row2, p));
}

SHARED_FN vec3 opScale(vec3 p, real s) { return p / s; }

// rotation about y by angle k*y (librarySin and libraryCos: transcendental.glsl's
// in float, which both backends compute bit for bit; the C library's in double)
SHARED_FN vec3 opTwist(vec3 p, real k) {
    real c = libraryCos(k * p.y);
    real s = librarySin(k * p.y);
    return vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}

// rotation about z by angle k*x
SHARED_FN vec3 opBend(vec3 p, real k) {
    real c = libraryCos(k * p.x);
    real s = librarySin(k * p.x);
    return vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}

SHARED_FN vec3 opElongate(vec3 p, vec3 h) { return p - clamp(p, -h, h); }

// mask components are 1 for mirrored axes, 0 otherwise
SHARED_FN vec3 opMirror(vec3 p, vec3 mask) {
    return vec3(mask.x > real(0.5) ? abs(p.x) : p.x,
                mask.y > real(0.5) ? abs(p.y) : p.y,
                mask.z > real(0.5) ? abs(p.z) : p.z);
}

// One axis of limited repetition: x - s * clamp(floor(x/s + 1/2), -l, l); s = 0 leaves x.
SHARED_FN real repeatAxis(real x, real spacing, real count) {
    if (spacing == real(0)) {
        return x;
    }
    return x - spacing * clamp(roundHalfUp(x / spacing), -count, count);
}

SHARED_FN vec3 opRepeat(vec3 p, vec3 spacing, vec3 counts) {
    return vec3(repeatAxis(p.x, spacing.x, counts.x),
                repeatAxis(p.y, spacing.y, counts.y),
                repeatAxis(p.z, spacing.z, counts.z));
}

// One axis of infinite repetition with period c (cells centred on multiples of c); c = 0 leaves x.
SHARED_FN real repeatInfiniteAxis(real x, real period) {
    if (period == real(0)) {
        return x;
    }
    return x - period * roundHalfUp(x / period);
}

SHARED_FN vec3 opRepeatInfinite(vec3 p, vec3 period) {
    return vec3(repeatInfiniteAxis(p.x, period.x),
                repeatInfiniteAxis(p.y, period.y),
                repeatInfiniteAxis(p.z, period.z));
}

// The displacement pattern: amplitude * sin(f x) sin(f y) sin(f z).
SHARED_FN real displacementPattern(vec3 p, real amplitude, real frequency) {
    return amplitude * librarySin(frequency * p.x) * librarySin(frequency * p.y) * librarySin(frequency * p.z);
}
