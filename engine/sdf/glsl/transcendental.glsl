// The transcendental built-ins of user formulas (sin, cos, tan, exp, log, pow),
// and in float the library's own sin and cos (twist, bend, displacement),
// written from + - * / floor and bit casts, which llvmpipe and the C++ build
// compute bit for bit (docs/toolchain-notes.md). llvmpipe's own sin and exp2
// are other polynomials than the C library's: a trusted `sdf` formula with sin
// differed by up to 75/255 between the backends once an overshooting march
// amplified the last bits. The float CPU evaluator (expr/tape.cpp) and the
// generated GLSL (expr/glsl.cpp) both call these; the double evaluator keeps the
// C library's, as the reference. Error: within 2 ulp of the true value for
// |x| < 1e4 (sin, cos), over the whole range otherwise (tests/expr).
// Polynomials after Cephes' single-precision sinf, cosf, expf and logf.

const real FORMULA_SMALLEST_NORMAL = real(1.17549435e-38);

// sin and cos of r, |r| <= pi/4
SHARED_FN real formulaSinKernel(real r) {
    real z = r * r;
    return r + r * z * (real(-1.6666654611e-1) + z * (real(8.3321608736e-3) + z * real(-1.9515295891e-4)));
}

SHARED_FN real formulaCosKernel(real r) {
    real z = r * r;
    return real(1) - real(0.5) * z +
           z * z * (real(4.166664568298827e-2) + z * (real(-1.388731625493765e-3) + z * real(2.443315711809948e-5)));
}

// x = r + n pi/2 with |r| <= pi/4; pi/2 in three parts, the first exact in
// 8 bits, so n times it is exact for |n| < 65536.
struct QuarterTurns {
    real r;
    real quadrant;  // n mod 4, in {0, 1, 2, 3}
};

SHARED_FN QuarterTurns formulaReduce(real x) {
    real n = floor(x * real(0.636619772) + real(0.5));
    real r = ((x - n * real(1.5703125)) - n * real(4.837512969970703125e-4)) - n * real(7.549789948768648e-8);
    return QuarterTurns(r, n - real(4) * floor(n * real(0.25)));
}

SHARED_FN real formulaSin(real x) {
    QuarterTurns q = formulaReduce(x);
    real value = q.quadrant == real(0) || q.quadrant == real(2) ? formulaSinKernel(q.r) : formulaCosKernel(q.r);
    return q.quadrant >= real(2) ? -value : value;
}

SHARED_FN real formulaCos(real x) {
    QuarterTurns q = formulaReduce(x);
    real value = q.quadrant == real(0) || q.quadrant == real(2) ? formulaCosKernel(q.r) : formulaSinKernel(q.r);
    return q.quadrant == real(1) || q.quadrant == real(2) ? -value : value;
}

SHARED_FN real formulaTan(real x) { return formulaSin(x) / formulaCos(x); }

// 2^n for an integer n in [-126, 127], exactly, from its bits.
SHARED_FN real formulaPowerOfTwo(real n) { return real(intBitsToFloat((int(n) + 127) * 8388608)); }

// exp(x) = 2^n e^r, ln 2 in two parts; below e^-87 (near the smallest normal
// float, which llvmpipe flushes below) 0, above e^88.7 infinity, in both
// backends alike.
SHARED_FN real formulaExp(real x) {
    if (x < real(-87)) {
        return real(0);
    }
    if (x > real(88.72283)) {
        return real(intBitsToFloat(2139095040));  // +infinity
    }
    real n = floor(x * real(1.44269504088896341) + real(0.5));
    real r = (x - n * real(0.693359375)) - n * real(-2.12194440e-4);
    real z = r * r;
    real p = (((((real(1.9875691500e-4) * r + real(1.3981999507e-3)) * r + real(8.3334519073e-3)) * r +
                real(4.1665795894e-2)) * r + real(1.6666665459e-1)) * r + real(5.0000001201e-1)) * z + r + real(1);
    // n = 128 (x within 88.72) needs two factors
    real firstHalf = floor(n * real(0.5));
    return p * formulaPowerOfTwo(firstHalf) * formulaPowerOfTwo(n - firstHalf);
}

// log(x) = e ln 2 + log(m), x = m 2^e with m in [sqrt(1/2), sqrt(2)), from
// the bits of x. Formulas guard their arguments to x >= the smallest normal
// float (expr/graph.cpp); below it, -infinity; infinity and NaN pass through.
SHARED_FN real formulaLog(real x) {
    if (!(x >= FORMULA_SMALLEST_NORMAL)) {
        return x != x ? x : real(intBitsToFloat(-8388608));  // NaN, or -infinity
    }
    if (x > real(3.40282347e38)) {
        return x;
    }
    int bits = floatBitsToInt(float(x));
    real e = real((bits / 8388608) - 126);
    real m = real(intBitsToFloat(bits - ((bits / 8388608) - 126) * 8388608));  // in [0.5, 1)
    if (m < real(0.707106781186547524)) {
        e = e - real(1);
        m = m + m - real(1);
    } else {
        m = m - real(1);
    }
    real z = m * m;
    real y = ((((((((real(7.0376836292e-2) * m - real(1.1514610310e-1)) * m + real(1.1676998740e-1)) * m -
                   real(1.2420140846e-1)) * m + real(1.4249322787e-1)) * m - real(1.6668057665e-1)) * m +
                real(2.0000714765e-1)) * m - real(2.4999993993e-1)) * m + real(3.3333331174e-1)) * m * z;
    y = y + e * real(-2.12194440e-4);
    y = y - real(0.5) * z;
    return (m + y) + e * real(0.693359375);
}

// Formulas guard the base of pow to x >= the smallest normal float. Like
// GLSL's exp2(y log2 x), its relative error grows with |y log x|: 2 ulps
// times that (1.5e-6 for 2^-126 to the power 0.5).
SHARED_FN real formulaPow(real x, real y) { return formulaExp(y * formulaLog(x)); }

// 2^x and log2(x) for the library's blends (librarySin's twins, shared_instance.inl):
// through exp and log, so within a few ulps more than those (the product with
// ln 2 rounds once); below the smallest normal float, as formulaLog.
SHARED_FN real formulaExp2(real x) { return formulaExp(x * real(0.693147180559945309)); }
SHARED_FN real formulaLog2(real x) { return formulaLog(x) * real(1.44269504088896341); }

// atan2(y, x) in (-pi, pi] for the environment map's angles: a minimax
// polynomial of the ratio of the smaller to the larger magnitude in [0, 1],
// within 1e-5 radians (a texel of a 4096-wide map is 1.5e-3); 0 at the origin.
SHARED_FN real formulaAtan2(real y, real x) {
    real ax = abs(x);
    real ay = abs(y);
    real larger = max(ax, ay);
    if (!(larger > real(0))) {
        return real(0);
    }
    real a = min(ax, ay) / larger;
    real s = a * a;
    real r = a * (real(0.99997726) +
                  s * (real(-0.33262347) +
                       s * (real(0.19354346) + s * (real(-0.11643287) + s * (real(0.05265332) + s * real(-0.0117212))))));
    if (ay > ax) {
        r = real(1.57079637) - r;
    }
    if (x < real(0)) {
        r = real(3.14159274) - r;
    }
    return y < real(0) ? -r : r;
}
