// Every opcode of the instruction set (program/opcodes.h) run through both
// backends on the same points and parameters: the CPU interpreter in float
// (cpu/interpreter.h) and the map() the GLSL generator writes, on llvmpipe.
// The points include the special ones a formula tends to get wrong (zero, -0,
// negative, tiny, huge, on and beside cell boundaries); each opcode has
// parameter sets of its own with degenerate values. Distance, safe step and
// every material slot must agree bit for bit. An opcode without a case below
// fails EveryOpcodeHasACase, so a new instruction cannot skip this suite.

#include <bit>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/interpreter.h"
#include "gl/shader_generator.h"
#include "gl_test_support.h"
#include "glcontext/fragment_evaluator.h"
#include "image/mipmapped_images.h"
#include "image/mipmaps.h"
#include "program/compile_scene.h"
#include "program/opcodes.h"
#include "program/scene_images.h"
#include "sdf/glsl_sources.h"

namespace sdfwb {
namespace {

using glm::dvec4;
using program::Instruction;
using program::OpClass;
using program::Opcode;
namespace shared = sdf::f64;

struct ConformanceCase {
    using Tolerance = std::int64_t (*)(int variant, size_t set);

    Opcode op;
    std::vector<std::vector<dvec4>> parameterSets;  // each with the opcode's paramSlots slots
    std::string formula;                            // the formula opcodes' source
    std::vector<int> variants;                      // smooth booleans: every SMOOTH_* code
    // Allowed difference in units of the last place of max(|CPU value|, 1) for
    // a variant and parameter set; null: bit for bit.
    Tolerance tolerance;

    ConformanceCase(Opcode o, std::vector<std::vector<dvec4>> sets, std::string source = "",
                    std::vector<int> codes = {0}, Tolerance allowed = nullptr)
        : op(o),
          parameterSets(std::move(sets)),
          formula(std::move(source)),
          variants(std::move(codes)),
          tolerance(allowed) {}
};

// The displacement's product of three library sines can be a unit of the last
// place apart (the sines alone agree bit for bit); not yet explained.
std::int64_t displaceTolerance(int, size_t) { return 2; }

constexpr double kHuge = 1e15;
constexpr double kTiny = 1e-12;

// Parameters: ordinary values first, then degenerate and extreme ones.
std::vector<ConformanceCase> conformanceCases() {
    const std::vector<int> smoothVariants = {shared::SMOOTH_POLYNOMIAL, shared::SMOOTH_EXPONENTIAL,
                                             shared::SMOOTH_POWER, shared::SMOOTH_ROOT};
    const std::vector<std::vector<dvec4>> smoothSets = {
        {dvec4(0.3, 2, 0, 0)}, {dvec4(kTiny, 8, 0, 0)}, {dvec4(2.5, 1, 0, 0)}, {dvec4(0, 2, 0, 0)}};
    return {
        {Opcode::Translate, {{dvec4(0.5, -1.25, 2, 0)}, {dvec4(0)}, {dvec4(-kHuge, kTiny, 1, 0)}}},
        {Opcode::Rotate,
         {{dvec4(0.6, 0, -0.8, 0), dvec4(0, 1, 0, 0), dvec4(0.8, 0, 0.6, 0)},
          {dvec4(1, 0, 0, 0), dvec4(0, 1, 0, 0), dvec4(0, 0, 1, 0)},
          {dvec4(0, 0, 1, 0), dvec4(1, 0, 0, 0), dvec4(0, 1, 0, 0)}}},
        {Opcode::Scale, {{dvec4(2, 0, 0, 0)}, {dvec4(0.25, 0, 0, 0)}, {dvec4(kTiny, 0, 0, 0)}}},
        {Opcode::Twist, {{dvec4(0.8, 0, 0, 0)}, {dvec4(0)}, {dvec4(-3, 0, 0, 0)}, {dvec4(1e4, 0, 0, 0)}}},
        {Opcode::Bend, {{dvec4(0.5, 0, 0, 0)}, {dvec4(0)}, {dvec4(-2, 0, 0, 0)}, {dvec4(1e4, 0, 0, 0)}}},
        {Opcode::Elongate, {{dvec4(0.5, 0, 1, 0)}, {dvec4(0)}, {dvec4(kHuge, kTiny, 1.5, 0)}}},
        {Opcode::Mirror, {{dvec4(1, 0, 1, 0)}, {dvec4(0)}, {dvec4(1, 1, 1, 0)}}},
        {Opcode::Repeat,
         {{dvec4(1, 0, 2, 0), dvec4(2, 0, 1, 0)},
          {dvec4(0.5, 0.5, 0.5, 0), dvec4(0)},
          {dvec4(1, 1, 1, 0), dvec4(1e6, 1e6, 1e6, 0)}}},
        {Opcode::RepeatInfinite, {{dvec4(1, 0, 0.5, 0)}, {dvec4(2, 2, 2, 0)}, {dvec4(kTiny, 3, 0, 0)}}},
        {Opcode::Sphere, {{dvec4(1, 0, 0, 0)}, {dvec4(0)}, {dvec4(kTiny, 0, 0, 0)}, {dvec4(kHuge, 0, 0, 0)}}},
        {Opcode::Box, {{dvec4(1, 0.5, 2, 0)}, {dvec4(0)}, {dvec4(kTiny, 1, kHuge, 0)}}},
        {Opcode::RoundBox, {{dvec4(1, 0.5, 2, 0.2)}, {dvec4(0.5, 0.5, 0.5, 0.5)}, {dvec4(1, 1, 1, 0)}}},
        {Opcode::Plane, {{dvec4(0.6, 0.8, 0, 0.25)}, {dvec4(0, 1, 0, 0)}, {dvec4(0, 0, -1, -kHuge)}}},
        {Opcode::Torus, {{dvec4(1, 0.3, 0, 0)}, {dvec4(0)}, {dvec4(kTiny, 2, 0, 0)}}},
        {Opcode::Cone, {{dvec4(0.5, 0.8660254, 1.5, 0)}, {dvec4(0, 1, 1, 0)}, {dvec4(1, 0, kTiny, 0)}}},
        {Opcode::Ellipsoid, {{dvec4(1.5, 0.7, 1, 0)}, {dvec4(1, 1, 1, 0)}, {dvec4(kTiny, 1, 2, 0)}}},
        {Opcode::Cylinder, {{dvec4(0.6, 1.1, 0, 0)}, {dvec4(0)}, {dvec4(kHuge, kTiny, 0, 0)}}},
        {Opcode::Capsule,
         {{dvec4(-0.5, -0.3, 0.1, 0.35), dvec4(0.5, 1, 0, 0)},
          {dvec4(1, 1, 1, 0.5), dvec4(1, 1, 1, 0)},
          {dvec4(0, 0, 0, 0), dvec4(0)}}},
        {Opcode::Ground,
         {{dvec4(-1, shared::GROUND_PLAIN, 0, 0), dvec4(0.25, 3, -2, 1), dvec4(0.1, 0.2, 0.3, 0.05)},
          {dvec4(-1, shared::GROUND_CHECKER, 0, 0), dvec4(0.25, 3, -2, 1), dvec4(0.1, 0.2, 0.3, 0.05)},
          {dvec4(0, shared::GROUND_GRID, 0, 0), dvec4(0, 0, 0, 0.5), dvec4(0.9, 0.8, 0.7, 0.1)},
          {dvec4(0, shared::GROUND_CHECKER, 0, 0), dvec4(kHuge, 0, -kHuge, 0.5), dvec4(0.9, 0.8, 0.7, 0.1)},
          {dvec4(0, shared::GROUND_CHECKER, 0, 0), dvec4(0, 0, 0, 0), dvec4(0.9, 0.8, 0.7, 0.1)},
          {dvec4(-1, shared::GROUND_CHECKER, 0.002, 0), dvec4(0.25, 3, -2, 1), dvec4(0.1, 0.2, 0.3, 0.05)},
          {dvec4(-1, shared::GROUND_GRID, 0.002, 0), dvec4(0.25, 3, -2, 0.5), dvec4(0.1, 0.2, 0.3, 0.04)},
          {dvec4(0, shared::GROUND_GRID, kHuge, 0), dvec4(0, 0, 0, 0.5), dvec4(0.9, 0.8, 0.7, 0.1)},
          // taken along the ray (tracing "bounded"): no step above the plane
          {dvec4(-1, shared::GROUND_PLAIN, 0, 1), dvec4(0.25, 3, -2, 1), dvec4(0.1, 0.2, 0.3, 0.05)},
          {dvec4(0.5, shared::GROUND_GRID, 0.002, 1), dvec4(0.25, 3, -2, 0.5), dvec4(0.1, 0.2, 0.3, 0.04)}}},
        {Opcode::SdfFormula,
         {{}},
         "let q = abs(p) - vec3(0.8, 0.5, 0.6); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - 0.15"},
        {Opcode::ImplicitFormula,
         {{dvec4(0, 0, 0, 0.5), dvec4(2, 2, 2, 0)},
          {dvec4(0.5, 0, 0, 0.25), dvec4(1.5, 1.5, 1.5, 0.05)},
          {dvec4(0, 0, 0, kTiny), dvec4(1e3, 1e3, 1e3, 0)}},
         "x^2*y^2 + y^2*z^2 + z^2*x^2 - x*y*z"},
        {Opcode::Union, {{}}},
        {Opcode::Intersection, {{}}},
        {Opcode::Difference, {{}}},
        {Opcode::SmoothUnion, smoothSets, "", smoothVariants},
        {Opcode::SmoothIntersection, smoothSets, "", smoothVariants},
        {Opcode::SmoothDifference, smoothSets, "", smoothVariants},
        {Opcode::ScaleDistance, {{dvec4(0.5, 0, 0, 0)}, {dvec4(0)}, {dvec4(kHuge, 0, 0, 0)}}},
        {Opcode::RoundDistance, {{dvec4(0.2, 0, 0, 0)}, {dvec4(0)}, {dvec4(-1, 0, 0, 0)}}},
        {Opcode::Displace, {{dvec4(0.1, 5, 0.5, 0)}, {dvec4(0)}, {dvec4(0.3, 1e4, 1, 0)}}, "", {0}, displaceTolerance},
        {Opcode::StepScale, {{dvec4(0.5, 0, 0, 0)}, {dvec4(0)}, {dvec4(1, 0, 0, 0)}}},
        {Opcode::Texture,
         {{dvec4(shared::TEXTURE_CHECKER, 4, 0.01, 0), dvec4(0.1, 0.2, 0.3, 0)},
          {dvec4(shared::TEXTURE_STRIPES, 1, 0, 0), dvec4(0.9, 0.8, 0.7, 0)},
          {dvec4(shared::TEXTURE_NOISE, 2.5, 0.002, 0), dvec4(0.5, 0.25, 0, 0)},
          {dvec4(shared::TEXTURE_NOISE, 1e3, kHuge, 0), dvec4(1, 1, 1, 0)},
          {dvec4(shared::TEXTURE_NONE, 1, 0.01, 0), dvec4(0, 0, 0, 0)}}},
        // q3: the test's texel pyramid (conformanceTexels), side 8, four levels
        {Opcode::ImageTexture,
         {{dvec4(shared::MAP_SPHERICAL, 0.01, 0, 0), dvec4(1.25, 1.25, 1.25, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_SPHERICAL, 0.3, 0, 0), dvec4(0.5, 2, 1e-3, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_BOX, 0.002, 0, 0), dvec4(0.5, 0.75, 1, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_PLANE, 0.05, 0, 0), dvec4(0, 1, 0, 4), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_PLANE, kHuge, 0, 0), dvec4(0.6, 0, 0.8, 1e3), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_CYLINDER, 0.01, 0, 0), dvec4(0.5, 1, 0, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_CONE, 0.01, 0, 0), dvec4(0.5, 0.866025, 1.5, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_TORUS, 0.01, 0, 0), dvec4(1, 0.25, 0, 0), dvec4(0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_CAPSULE, 0.01, 0, 0), dvec4(0, -1, 0, 0.5), dvec4(0.3, 1, 0.2, 0), dvec4(0, 8, 4, 0)},
          {dvec4(shared::MAP_CAPSULE, 0.01, 0, 0), dvec4(1, 1, 1, 0.5), dvec4(1, 1, 1, 0), dvec4(0, 8, 4, 0)}}},
        {Opcode::TriplanarTexture,
         {{dvec4(4, 0.01, 0, 0), dvec4(0, 8, 4, 0)},
          {dvec4(0.5, 0.3, 0, 0), dvec4(0, 8, 4, 0)},
          {dvec4(1e3, kHuge, 0, 0), dvec4(0, 8, 4, 0)}},
         "let q = abs(p) - vec3(0.8, 0.5, 0.6); length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - 0.15"},
        {Opcode::Bump,
         {{dvec4(shared::BUMP_NOISE, 4, 0.01, 0.02)},
          {dvec4(shared::BUMP_WAVES, 2.5, 0.002, 0.5)},
          {dvec4(shared::BUMP_NOISE, 1e3, kHuge, 1)},
          {dvec4(shared::BUMP_NONE, 1, 0.01, 1)}}},
        {Opcode::Empty, {{}}},
    };
}

// Coordinates every point draws from: zero of both signs, tiny and huge
// values, and the cell boundaries of the periods above (halves and wholes)
// with their float neighbours.
std::vector<float> specialCoordinates() {
    std::vector<float> c = {0.0f, -0.0f, 1e-12f, -1e-12f, 1.0f, -1.0f, -2.5f, 3.0f, 1e15f, -1e15f};
    for (float boundary : {0.5f, -1.5f}) {
        c.push_back(boundary);
        c.push_back(std::nextafter(boundary, 0.0f));
        c.push_back(std::nextafter(boundary, 2.0f * boundary));
    }
    return c;
}

constexpr int kWidth = 64;  // a 64 x 128 evaluation: every special triple, then random points
constexpr int kHeight = 128;
constexpr int kPoints = kWidth * kHeight;

// Every triple of special coordinates, then seeded random points in [-3, 3]^3.
std::vector<float> evaluationPoints() {
    std::vector<float> c = specialCoordinates();
    std::vector<float> xyzw;
    for (float x : c) {
        for (float y : c) {
            for (float z : c) xyzw.insert(xyzw.end(), {x, y, z, 0.0f});
        }
    }
    std::mt19937 random(9);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
    while (xyzw.size() < static_cast<size_t>(kPoints) * 4) {
        xyzw.insert(xyzw.end(), {coordinate(random), coordinate(random), coordinate(random), 0.0f});
    }
    xyzw.resize(static_cast<size_t>(kPoints) * 4);
    return xyzw;
}

// A program around one instruction of `c.op`, wired by its operand class.
// Slots after the scene-wide blocks: two materials, the instruction's
// parameters, then those of the operand shapes. A point instruction's result
// is read through a plane probe p . n, whose normal is the last slot.
struct ConformanceProgram {
    program::Program program;
    int opParam = -1;    // the instruction's first parameter slot
    int probeSlot = -1;  // point instructions: the probe's normal
};

ConformanceProgram conformanceProgram(const ConformanceCase& c, int variant) {
    const program::OpcodeInfo& info = program::opcodeInfo(c.op);
    ConformanceProgram out;
    program::Program& p = out.program;
    p.params.assign(static_cast<size_t>(shared::MATERIAL_SLOT), dvec4(0));
    auto addMaterial = [&](glm::dvec3 color, double shininess, double emission) {
        shared::Material m{.ambient = color * 0.25,
                           .diffuse = color,
                           .specular = glm::dvec3(0.5),
                           .shininess = shininess,
                           .emission = glm::dvec3(emission),
                           .emissionStrength = 1.5,
                           // every member differs between materials, so blends mix each of them
                           .reflectivity = shininess / 128,
                           .reflectionColor = color * 0.5,
                           .transparency = 1 - shininess / 64,
                           .transmissionColor = glm::dvec3(1) - color,
                           .ior = 1 + shininess / 64,
                           .fresnel = emission > 0 ? 1.0 : 0.0,
                           .bump = 0.0};
        int slot = static_cast<int>(p.params.size());
        for (int i = 0; i < shared::MATERIAL_SLOTS; ++i) p.params.push_back(shared::materialSlot(m, i));
        return slot;
    };
    addMaterial(glm::dvec3(0.7), 16, 0);  // the default material at MATERIAL_SLOT
    const int first = addMaterial(glm::dvec3(0.9, 0.2, 0.1), 32, 0.1);
    const int second = addMaterial(glm::dvec3(0.1, 0.3, 0.95), 4, 0);
    auto addSlots = [&](int count) {
        int slot = static_cast<int>(p.params.size());
        p.params.resize(p.params.size() + static_cast<size_t>(count), dvec4(0));
        return slot;
    };
    out.opParam = info.paramSlots > 0 ? addSlots(info.paramSlots) : -1;
    int formula = -1;
    if (!c.formula.empty()) {
        const bool implicit = info.opClass == OpClass::FormulaSample;
        const bool gradient = implicit || info.opClass == OpClass::FormulaImageTexture;
        p.formulas.push_back(program::compileFormula(
            c.formula, implicit ? program::FormulaLanguage::Implicit : program::FormulaLanguage::Sdf, gradient));
        formula = 0;
    }
    auto shape = [&](Opcode op, int dst, int point, dvec4 q, int material) {
        int slot = addSlots(1);
        p.params[static_cast<size_t>(slot)] = q;
        p.code.push_back({op, dst, point, -1, slot, material, 0});
    };
    const int v = formula >= 0 ? formula : variant;
    switch (info.opClass) {
    case OpClass::Point:
        p.pointRegisters = 2;
        p.code.push_back({c.op, 1, 0, -1, out.opParam, -1, 0});
        out.probeSlot = addSlots(1);
        p.code.push_back({Opcode::Plane, 0, 1, -1, out.probeSlot, first, 0});
        break;
    case OpClass::Shape:
    case OpClass::ShapeSample:
    case OpClass::FormulaShape:
    case OpClass::FormulaSample: p.code.push_back({c.op, 0, 0, -1, out.opParam, first, v}); break;
    case OpClass::Combine:
    case OpClass::SmoothCombine:
        p.sampleRegisters = 3;
        shape(Opcode::Sphere, 0, 0, dvec4(1.25, 0, 0, 0), first);
        shape(Opcode::Plane, 1, 0, dvec4(0.6, 0.8, 0, 0.25), second);
        p.code.push_back({c.op, 2, 0, 1, out.opParam, -1, v});
        p.result = 2;
        break;
    case OpClass::Post:
    case OpClass::Texture:
    case OpClass::ImageTexture:
    case OpClass::FormulaImageTexture:
        p.sampleRegisters = 2;
        shape(Opcode::Sphere, 0, 0, dvec4(1.25, 0, 0, 0), first);
        p.code.push_back({c.op, 1, 0, 0, out.opParam, -1, 0});
        p.result = 1;
        break;
    case OpClass::Constant: p.code.push_back({c.op, 0, -1, -1, -1, -1, 0}); break;
    }
    return out;
}

// What one evaluation reads back per point: view 0 is (d, step, bump, 0),
// views 1 to MATERIAL_SLOTS the material's slots.
constexpr std::string_view kMain = R"(
uniform samplerBuffer uPoints;
uniform int uView;
// as the renderer's outputs: Mesa then rounds every operation as written
invariant evalResult;
void main() {
    vec4 p = texelFetch(uPoints, evalIndex());
    Sample s = map(vec3(p.x, p.y, p.z));
    evalResult = uView == 0 ? vec4(s.d, s.step, s.material.bump, 0.0) : materialSlot(s.material, uView - 1);
}
)";

// Units in the last place between the two results: 0 when bit-identical, where
// llvmpipe's flushing denormals to zero (and losing a zero's sign) is allowed.
std::int64_t ulpsApart(float cpu, float gl) {
    if (std::isnan(cpu) || std::isnan(gl)) return std::isnan(cpu) && std::isnan(gl) ? 0 : INT64_MAX;
    if (std::fpclassify(cpu) == FP_SUBNORMAL) cpu = 0.0f;
    if (std::fpclassify(gl) == FP_SUBNORMAL) gl = 0.0f;
    auto key = [](float f) {
        if (f == 0.0f) return std::int64_t(0);
        auto bits = std::bit_cast<std::int32_t>(f);
        return bits < 0 ? std::int64_t(INT32_MIN) - bits : std::int64_t(bits);
    };
    return std::abs(key(cpu) - key(gl));
}

// |cpu - gl| in units of the last place of max(|cpu|, 1): a tolerance for
// results that may pass through zero.
std::int64_t unitUlpsApart(float cpu, float gl) {
    if (std::isnan(cpu) || std::isnan(gl) || std::isinf(cpu) || std::isinf(gl)) return ulpsApart(cpu, gl);
    float scale = std::max(std::abs(cpu), 1.0f);
    double ulp = double(std::nextafter(scale, INFINITY)) - double(scale);
    return static_cast<std::int64_t>(std::ceil(std::abs(double(cpu) - double(gl)) / ulp));
}

// The image the ImageTexture cases sample: side 8 with every texel distinct,
// and its mipmaps, as the texel buffer's only image.
program::ResolvedImages conformanceTexels() {
    std::vector<glm::vec4> level0;
    for (int i = 0; i < 64; ++i)
        level0.emplace_back(0.01f * float(i), 1.0f - 0.013f * float(i), 0.1f + float(i % 7) * 0.1f, 1);
    auto images = std::make_shared<image::MipmappedImages>();
    images->side = 8;
    images->levels = 4;
    images->texels = image::buildMipmaps(level0, 8);
    program::ResolvedImages out;
    out.environment = images;
    return out;
}


class OpcodeConformance : public test::GlTest {
protected:
    // Runs one case on every point with every parameter set and variant;
    // returns the number of disagreeing floats, printing the first few.
    int mismatches(const ConformanceCase& c) {
        const std::vector<float> points = evaluationPoints();
        int bad = 0;
        for (int variant : c.variants) {
            ConformanceProgram built = conformanceProgram(c, variant);
            const OpClass opClass = program::opcodeInfo(c.op).opClass;
            texels_ = opClass == OpClass::ImageTexture || opClass == OpClass::FormulaImageTexture;
            std::string source = std::string(sdf::glslPrelude()) + gl::smoothVariantDefines(built.program) +
                                 std::string(sdf::glslLibrary()) +
                                 std::string(gl::parameterAccessSource()) + gl::textureAccessSource(texels_) +
                                 gl::generateMapFunction(built.program) + std::string(kMain);
            glcontext::FragmentEvaluator evaluator(gl(), source);
            const bool pointOp = program::opcodeInfo(c.op).opClass == OpClass::Point;
            for (size_t set = 0; set < c.parameterSets.size(); ++set) {
                const std::int64_t tolerance = c.tolerance ? c.tolerance(variant, set) : 0;
                // point instructions: three probes x, y, z of the moved point; otherwise the sample's views
                const int runs = pointOp ? 3 : 1 + shared::MATERIAL_SLOTS;
                for (int run = 0; run < runs; ++run) {
                    program::Program& p = built.program;
                    for (size_t i = 0; i < c.parameterSets[set].size(); ++i) {
                        p.params[static_cast<size_t>(built.opParam) + i] = c.parameterSets[set][i];
                    }
                    if (pointOp) {
                        p.params[static_cast<size_t>(built.probeSlot)] = dvec4(0);
                        p.params[static_cast<size_t>(built.probeSlot)][run] = 1.0;
                    }
                    const int view = pointOp ? 0 : run;
                    std::string where = std::string(program::opcodeInfo(c.op).name) + " variant " +
                                        std::to_string(variant) + " parameter set " + std::to_string(set) +
                                        (pointOp ? " probe " : " view ") + std::to_string(run);
                    bad += compare(evaluator, p, points, view, tolerance, where);
                }
            }
        }
        return bad;
    }

    std::int64_t worstUlps_ = 0;
    std::string worstReport_;

private:
    bool texels_ = false;  // the case reads the texel buffer
    program::ResolvedImages images_ = conformanceTexels();

    int compare(const glcontext::FragmentEvaluator& evaluator, const program::Program& p,
                const std::vector<float>& points, int view, std::int64_t tolerance, const std::string& where) {
        std::vector<float> params;
        std::vector<cpu::f32::vec4> cpuParams;
        for (const dvec4& q : p.params) {
            cpuParams.push_back(cpu::f32::vec4(q));
            params.insert(params.end(),
                          {cpuParams.back().x, cpuParams.back().y, cpuParams.back().z, cpuParams.back().w});
        }
        gl().UseProgram(evaluator.program());
        gl().Uniform1i(gl().GetUniformLocation(evaluator.program(), "uView"), view);
        gl().UseProgram(0);
        std::vector<glcontext::EvaluatorInput> inputs = {{"uParams", 4, glcontext::InputLayout::Buffer, params}};
        // the constant's map() ignores its point, and the evaluator refuses an input the shader does not read
        if (!p.code.empty() && p.code.back().op != Opcode::Empty) {
            inputs.push_back({"uPoints", 4, glcontext::InputLayout::Buffer, points});
        }
        if (texels_) {
            const auto& t = images_.environment->texels;
            inputs.push_back({"uTexels", 4, glcontext::InputLayout::Buffer,
                              std::vector<float>(&t.front().x, &t.front().x + t.size() * 4)});
        }
        std::vector<float> got = evaluator.evaluate(gl(), kWidth, kHeight, inputs);

        cpu::f32::Scratch scratch(p);
        int bad = 0;
        for (int i = 0; i < kPoints; ++i) {
            const float* q = &points[static_cast<size_t>(i) * 4];
            cpu::f32::Sample s =
                cpu::f32::runCode(p.code, p.result, cpuParams.data(), scratch, cpu::f32::vec3(q[0], q[1], q[2]),
                                  cpu::f32::Texels{texels_ ? &images_ : nullptr});
            cpu::f32::vec4 expected =
                view == 0 ? cpu::f32::vec4(s.d, s.step, s.material.bump, 0.0f) : cpu::f32::materialSlot(s.material, view - 1);
            for (int k = 0; k < 4; ++k) {
                float g = got[static_cast<size_t>(i) * 4 + static_cast<size_t>(k)];
                std::int64_t ulps = tolerance == 0 ? ulpsApart(expected[k], g) : unitUlpsApart(expected[k], g);
                if (ulps > worstUlps_) {
                    worstUlps_ = ulps;
                    std::ostringstream report;
                    report << std::setprecision(9) << where << ", point (" << q[0] << ", " << q[1] << ", " << q[2]
                           << "), component " << k << ": CPU " << expected[k] << ", GL " << g;
                    worstReport_ = report.str();
                }
                if (ulps <= tolerance) continue;
                if (++bad <= 5) {
                    std::cout << std::setprecision(9) << where << ", point (" << q[0] << ", " << q[1] << ", " << q[2]
                              << "), component " << k << ": CPU " << expected[k] << ", GL " << g << "\n";
                }
            }
        }
        return bad;
    }
};

TEST(OpcodeConformanceTable, EveryOpcodeHasACase) {
    std::vector<ConformanceCase> cases = conformanceCases();
    for (const program::OpcodeInfo& info : program::kOpcodes) {
        int found = 0;
        for (const ConformanceCase& c : cases) {
            if (c.op != info.op) continue;
            ++found;
            for (const std::vector<dvec4>& set : c.parameterSets) {
                EXPECT_EQ(static_cast<int>(set.size()), info.paramSlots) << info.name << ": a parameter set's slots";
            }
            bool formulaOp = info.opClass == OpClass::FormulaShape || info.opClass == OpClass::FormulaSample ||
                             info.opClass == OpClass::FormulaImageTexture;
            EXPECT_EQ(formulaOp, !c.formula.empty()) << info.name << ": a formula opcode needs a formula";
        }
        EXPECT_EQ(found, 1) << "opcode " << info.name << " needs exactly one case in conformanceCases()";
    }
}

TEST(OpcodeConformanceTable, PointsCoverEverySpecialTriple) {
    size_t specials = specialCoordinates().size();
    EXPECT_LE(specials * specials * specials, static_cast<size_t>(kPoints) / 2) << "room for random points";
}

TEST_F(OpcodeConformance, EveryOpcodeAgreesBitForBit) {
    for (const ConformanceCase& c : conformanceCases()) {
        SCOPED_TRACE(std::string(program::opcodeInfo(c.op).name));
        worstUlps_ = 0;
        EXPECT_EQ(mismatches(c), 0) << program::opcodeInfo(c.op).name;
        std::cout << program::opcodeInfo(c.op).name << ": worst " << worstUlps_ << " ulps " << worstReport_ << "\n";
    }
}

}  // namespace
}  // namespace sdfwb
