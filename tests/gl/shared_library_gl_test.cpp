// Every built-in the shared SDF library relies on, and its functions, run in
// GLSL on llvmpipe and in the float C++ build on the same inputs. Where the
// results must agree bit for bit the test says so; where llvmpipe uses its own
// approximations (sin, cos, exp2, log2) it bounds the difference.

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <random>
#include <regex>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"
#include "sdf/glsl_sources.h"
#include "sdf/shared.h"

namespace sdfwb {
namespace {

using namespace sdf::f32;

constexpr int kCount = 4096;  // inputs per function, a 64 x 64 evaluation

struct Inputs {
    std::vector<float> a, b;  // kCount vec4 each
};

Inputs makeInputs(float range, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> value(-range, range);
    Inputs in;
    for (int i = 0; i < kCount * 4; ++i) {
        in.a.push_back(value(random));
        in.b.push_back(value(random));
    }
    // exact special values the guards are for
    for (int c = 0; c < 4; ++c) {
        in.a[static_cast<size_t>(c)] = 0.0f;
        in.a[static_cast<size_t>(4 + c)] = 0.5f;
        in.a[static_cast<size_t>(8 + c)] = -0.5f;
    }
    return in;
}

// Units in the last place between two floats (0 when bit-identical).
std::int64_t ulps(float x, float y) {
    if (std::isnan(x) || std::isnan(y)) return (std::isnan(x) && std::isnan(y)) ? 0 : INT64_MAX;
    auto key = [](float f) {
        auto bits = std::bit_cast<std::int32_t>(f);
        return bits < 0 ? std::int64_t(INT32_MIN) - bits : std::int64_t(bits);
    };
    return std::abs(key(x) - key(y));
}

class SharedLibraryOnGl : public test::GlTest {
protected:
    // Runs `glslBody` (a GLSL expression of vec4 a, vec4 b giving a vec4) and
    // `cpp` on the same inputs; returns the largest ulp difference seen.
    std::int64_t maxUlps(const std::string& glslBody, const std::function<vec4(vec4, vec4)>& cpp, float range = 4.0f,
                         unsigned seed = 1) {
        // the evaluator rejects inputs the shader does not read, so pass b only when used
        bool usesB = std::regex_search(glslBody, std::regex("\\bb\\b"));
        std::string source = std::string(sdf::glslPrelude()) + std::string(sdf::glslLibrary()) +
                             // as the renderer's outputs: Mesa then rounds every operation as written
                             "invariant evalResult;\n"
                             "uniform samplerBuffer inA;\nuniform samplerBuffer inB;\n"
                             "void main() {\n  vec4 a = texelFetch(inA, evalIndex());\n"
                             "  vec4 b = texelFetch(inB, evalIndex());\n  evalResult = " +
                             glslBody + ";\n}\n";
        glcontext::FragmentEvaluator evaluator(gl(), source);
        Inputs in = makeInputs(range, seed);
        std::vector<glcontext::EvaluatorInput> inputs = {{"inA", 4, glcontext::InputLayout::Buffer, in.a}};
        if (usesB) inputs.push_back({"inB", 4, glcontext::InputLayout::Buffer, in.b});
        std::vector<float> got = evaluator.evaluate(gl(), 64, 64, inputs);
        std::int64_t worst = 0;
        worstAbsolute_ = 0;
        for (int i = 0; i < kCount; ++i) {
            size_t k = static_cast<size_t>(i) * 4;
            vec4 expected = cpp(vec4(in.a[k], in.a[k + 1], in.a[k + 2], in.a[k + 3]),
                                vec4(in.b[k], in.b[k + 1], in.b[k + 2], in.b[k + 3]));
            for (int c = 0; c < 4; ++c) {
                float e = expected[c];
                if (e == 0.0f || std::fpclassify(e) == FP_SUBNORMAL) e = 0.0f;  // llvmpipe flushes denormals
                float g = got[k + static_cast<size_t>(c)];
                if (std::fpclassify(g) == FP_SUBNORMAL) g = 0.0f;
                if (ulps(g, e) > worst) {
                    worst = ulps(g, e);
                    worstReport_ = "component " + std::to_string(c) + " of input " + std::to_string(i) + ": GL " +
                                   std::to_string(g) + ", C++ " + std::to_string(e);
                }
                worstAbsolute_ = std::max(worstAbsolute_, double(std::abs(g - e)) / std::max(1.0, double(std::abs(e))));
            }
        }
        if (worst > 0) std::cout << glslBody << ": worst " << worst << " ulp at " << worstReport_ << "\n";
        return worst;
    }

    // Largest |GL - C++| / max(1, |C++|) of the last maxUlps() call.
    double worstRelative() const { return worstAbsolute_; }

private:
    std::string worstReport_;
    double worstAbsolute_ = 0;
};

vec3 v3(vec4 a) { return vec3(a.x, a.y, a.z); }

TEST_F(SharedLibraryOnGl, ExactBuiltinsAgreeBitForBit) {
    EXPECT_EQ(maxUlps("vec4(a.x + b.x, a.y - b.y, a.z * b.z, a.w / (abs(b.w) + 0.5))",
                      [](vec4 a, vec4 b) { return vec4(a.x + b.x, a.y - b.y, a.z * b.z, a.w / (std::abs(b.w) + 0.5f)); }),
              0);
    EXPECT_EQ(maxUlps("vec4(sqrt(abs(a.x)), inversesqrt(abs(a.y) + 0.001), floor(a.z), abs(a.w))",
                      [](vec4 a, vec4) {
                          return vec4(std::sqrt(std::abs(a.x)), glm::inversesqrt(std::abs(a.y) + 0.001f),
                                      std::floor(a.z), std::abs(a.w));
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(min(a.x, b.x), max(a.y, b.y), clamp(a.z, -1.0, 1.0), clamp(a.w, b.w, b.w + 1.0))",
                      [](vec4 a, vec4 b) {
                          return vec4(std::min(a.x, b.x), std::max(a.y, b.y), glm::clamp(a.z, -1.0f, 1.0f),
                                      glm::clamp(a.w, b.w, b.w + 1.0f));
                      }),
              0);
}

TEST_F(SharedLibraryOnGl, OwnVectorMathAgreesBitForBit) {
    EXPECT_EQ(maxUlps("vec4(dot3(a.xyz, b.xyz), length3(a.xyz), length2d(a.xy), modr(a.w, b.w))",
                      [](vec4 a, vec4 b) {
                          return vec4(dot3(v3(a), v3(b)), length3(v3(a)), length2d(vec2(a.x, a.y)), modr(a.w, b.w));
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(normalize3(a.xyz), roundHalfUp(a.w * 4.0))",
                      [](vec4 a, vec4) {
                          vec3 n = normalize3(v3(a));
                          return vec4(n.x, n.y, n.z, roundHalfUp(a.w * 4.0f));
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(lerp3s(a.xyz, b.xyz, 0.3), smoothstepr(-1.0, 1.0, a.w))",
                      [](vec4 a, vec4 b) {
                          vec3 l = lerp3s(v3(a), v3(b), 0.3f);
                          return vec4(l.x, l.y, l.z, smoothstepr(-1.0f, 1.0f, a.w));
                      }),
              0);
    // equal edges are step(edge, x) (the guard rule of docs/shared-glsl-subset.md); any other order is arithmetic
    EXPECT_EQ(maxUlps("vec4(smoothstepr(a.x, a.x, b.x), smoothstepr(a.y, a.y, a.y), smoothstepr(b.z, a.z, a.w), 0.0)",
                      [](vec4 a, vec4 b) {
                          return vec4(smoothstepr(a.x, a.x, b.x), smoothstepr(a.y, a.y, a.y),
                                      smoothstepr(b.z, a.z, a.w), 0.0f);
                      }),
              0);
}

// Parameters come from b (a buffer) rather than literals, as in generated
// shaders: Mesa reassociates arithmetic with constant operands, so
// `dot3(p, vec3(0.6, 0.8, 0.0)) - 0.25` written with literals differs by an ulp.
TEST_F(SharedLibraryOnGl, PrimitivesAgreeBitForBit) {
    EXPECT_EQ(maxUlps("vec4(sdSphere(a.xyz, 1.3), sdBox(a.xyz, vec3(1.0, 0.5, 2.0)), "
                      "sdRoundBox(a.xyz, vec3(1.0, 0.5, 2.0), 0.2), sdPlane(a.xyz, normalize3(b.xyz), b.w))",
                      [](vec4 a, vec4 b) {
                          vec3 p = v3(a);
                          return vec4(sdSphere(p, 1.3f), sdBox(p, vec3(1.0f, 0.5f, 2.0f)),
                                      sdRoundBox(p, vec3(1.0f, 0.5f, 2.0f), 0.2f), sdPlane(p, normalize3(v3(b)), b.w));
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(sdTorus(a.xyz, 1.0, 0.3), sdCone(a.xyz, vec2(0.5, 0.8660254), 1.5), "
                      "sdEllipsoid(a.xyz, vec3(1.5, 0.7, 1.0)), sdCylinder(a.xyz, 0.6, 1.1))",
                      [](vec4 a, vec4) {
                          vec3 p = v3(a);
                          return vec4(sdTorus(p, 1.0f, 0.3f), sdCone(p, vec2(0.5f, 0.8660254f), 1.5f),
                                      sdEllipsoid(p, vec3(1.5f, 0.7f, 1.0f)), sdCylinder(p, 0.6f, 1.1f));
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(sdCapsule(a.xyz, vec3(-0.5, -0.3, 0.1), b.xyz, 0.35), 0.0, 0.0, 0.0)",
                      [](vec4 a, vec4 b) {
                          return vec4(sdCapsule(v3(a), vec3(-0.5f, -0.3f, 0.1f), v3(b), 0.35f), 0.0f, 0.0f, 0.0f);
                      }),
              0);
}

TEST_F(SharedLibraryOnGl, PointOperatorsWithoutTrigonometryAgreeBitForBit) {
    EXPECT_EQ(maxUlps("vec4(opRepeat(a.xyz, vec3(0.7, 0.0, 1.3), vec3(2.0, 0.0, 1.0)), 0.0)",
                      [](vec4 a, vec4) {
                          vec3 r = opRepeat(v3(a), vec3(0.7f, 0.0f, 1.3f), vec3(2.0f, 0.0f, 1.0f));
                          return vec4(r.x, r.y, r.z, 0.0f);
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(opRepeatInfinite(a.xyz, vec3(0.5, 0.0, 0.25)), 0.0)",
                      [](vec4 a, vec4) {
                          vec3 r = opRepeatInfinite(v3(a), vec3(0.5f, 0.0f, 0.25f));
                          return vec4(r.x, r.y, r.z, 0.0f);
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(opRotate(a.xyz, vec3(0.6, 0.0, -0.8), vec3(0.0, 1.0, 0.0), vec3(0.8, 0.0, 0.6)), 0.0)",
                      [](vec4 a, vec4) {
                          vec3 r = opRotate(v3(a), vec3(0.6f, 0.0f, -0.8f), vec3(0.0f, 1.0f, 0.0f), vec3(0.8f, 0.0f, 0.6f));
                          return vec4(r.x, r.y, r.z, 0.0f);
                      }),
              0);
    EXPECT_EQ(maxUlps("vec4(opElongate(a.xyz, vec3(0.5, 0.0, 1.0)) + opMirror(b.xyz, vec3(1.0, 0.0, 1.0)), 0.0)",
                      [](vec4 a, vec4 b) {
                          vec3 r = opElongate(v3(a), vec3(0.5f, 0.0f, 1.0f)) + opMirror(v3(b), vec3(1.0f, 0.0f, 1.0f));
                          return vec4(r.x, r.y, r.z, 0.0f);
                      }),
              0);
}

TEST_F(SharedLibraryOnGl, BooleansWithoutTranscendentalsAgreeBitForBit) {
    EXPECT_EQ(maxUlps("vec4(sminPolynomial(a.x, b.x, 0.5, 2.0).d, sminPolynomial(a.y, b.y, 0.5, 3.0).w, "
                      "sminRoot(a.z, b.z, 0.4).d, smoothMax(SMOOTH_ROOT, a.w, b.w, 0.4, 2.0).w)",
                      [](vec4 a, vec4 b) {
                          return vec4(sminPolynomial(a.x, b.x, 0.5f, 2.0f).d, sminPolynomial(a.y, b.y, 0.5f, 3.0f).w,
                                      sminRoot(a.z, b.z, 0.4f).d, smoothMax(SMOOTH_ROOT, a.w, b.w, 0.4f, 2.0f).w);
                      }),
              0);
}

// The formula language's transcendental built-ins (sdf/glsl/transcendental.glsl):
// built from + - * / floor and bit casts, bit for bit, over wide ranges (the
// special values 0 and +-0.5 included by makeInputs).
TEST_F(SharedLibraryOnGl, FormulaTranscendentalsAgreeBitForBit) {
    EXPECT_EQ(maxUlps("vec4(formulaSin(a.x), formulaCos(a.y), formulaTan(a.z), formulaSin(a.w * b.w))",
                      [](vec4 a, vec4 b) {
                          return vec4(formulaSin(a.x), formulaCos(a.y), formulaTan(a.z), formulaSin(a.w * b.w));
                      },
                      60.0f),
              0);
    EXPECT_EQ(maxUlps("vec4(formulaExp(a.x), formulaLog(abs(a.y)), formulaLog(abs(a.z) * b.z * b.z), formulaExp(a.w * b.w))",
                      [](vec4 a, vec4 b) {
                          return vec4(formulaExp(a.x), formulaLog(std::abs(a.y)), formulaLog(std::abs(a.z) * b.z * b.z),
                                      formulaExp(a.w * b.w));
                      },
                      12.0f, 2),
              0);
    EXPECT_EQ(maxUlps("vec4(formulaPow(abs(a.x), b.x), formulaPow(abs(a.y) + 0.001, b.y * 0.25), formulaCos(a.z * 1000.0), formulaLog(abs(a.w) + 1.0))",
                      [](vec4 a, vec4 b) {
                          return vec4(formulaPow(std::abs(a.x), b.x), formulaPow(std::abs(a.y) + 0.001f, b.y * 0.25f),
                                      formulaCos(a.z * 1000.0f), formulaLog(std::abs(a.w) + 1.0f));
                      },
                      8.0f, 3),
              0);
}

// llvmpipe evaluates sin, cos, exp2 and log2 with its own approximations
// (measured: sin/cos within 1 ulp, exp2/log2 within ~1e-7 relative); this
// bounds how far that moves the shared functions that use them.
TEST_F(SharedLibraryOnGl, TranscendentalsStayWithinSinglePrecisionNoise) {
    maxUlps("vec4(sin(a.x), cos(a.y), sin(a.z * 3.0), cos(a.w * 3.0))", [](vec4 a, vec4) {
        return vec4(std::sin(a.x), std::cos(a.y), std::sin(a.z * 3.0f), std::cos(a.w * 3.0f));
    });
    EXPECT_LE(worstRelative(), 1e-6);
    maxUlps("vec4(exp2(a.x), log2(abs(a.y) + 0.01), exp2(-abs(a.z) * 4.0), log2(abs(a.w) + 1.0))", [](vec4 a, vec4) {
        return vec4(std::exp2(a.x), std::log2(std::abs(a.y) + 0.01f), std::exp2(-std::abs(a.z) * 4.0f),
                    std::log2(std::abs(a.w) + 1.0f));
    });
    EXPECT_LE(worstRelative(), 1e-6);
    maxUlps("vec4(opTwist(a.xyz, 1.7), sminExponential(a.w, b.w, 0.5).d)", [](vec4 a, vec4 b) {
        vec3 t = opTwist(v3(a), 1.7f);
        return vec4(t.x, t.y, t.z, sminExponential(a.w, b.w, 0.5f).d);
    });
    EXPECT_LE(worstRelative(), 1e-5);
    maxUlps("vec4(opBend(a.xyz, 0.9), sminPower(abs(a.w), abs(b.w), 0.3).d)", [](vec4 a, vec4 b) {
        vec3 t = opBend(v3(a), 0.9f);
        return vec4(t.x, t.y, t.z, sminPower(std::abs(a.w), std::abs(b.w), 0.3f).d);
    });
    EXPECT_LE(worstRelative(), 1e-5);
}

}  // namespace
}  // namespace sdfwb
