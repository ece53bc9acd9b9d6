#include "gl/shader_generator.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

#include "expr/glsl.h"
#include "gl/fold_run.h"
#include "gl/program_size.h"
#include "prune/prune_grid.h"
#include "scene/node_kinds.h"
#include "sdf/glsl_sources.h"
#include "sdf/shared.h"

namespace sdfwb::gl {

using program::Instruction;
using program::OpClass;
using program::opcodeInfo;

namespace {

// The parameter buffer and its accessors, which map() and the tracer read.
constexpr std::string_view kParameters = R"(
uniform samplerBuffer uParams;
vec4 P(int slot) { return texelFetch(uParams, slot); }
Material M(int slot) {
    return materialFromSlots(P(slot), P(slot + 1), P(slot + 2), P(slot + 3), P(slot + 4), P(slot + 5));
}
)";

// The texel buffer of the scene's images (program/scene_images.h), read by
// mipmap_lookup.glsl; scenes without an environment map or an image texture
// read none.
constexpr std::string_view kTexels = R"(
uniform samplerBuffer uTexels;
vec4 T(int i) { return texelFetch(uTexels, i); }
)";
constexpr std::string_view kNoTexels = "vec4 T(int i) { return vec4(0.0); }\n";
// Set by the driver (sample_driver.glsl) before each evaluation: the footprint
// factor of image textures (0: no colour needed) and the shift of the point
// footprints are measured from (footprint_point.glsl; w = 0: none).
constexpr std::string_view kFootprintGlobals = R"(
float textureStretch = 1.0;
void setTextureStretch(float k) { textureStretch = k; }
vec4 footprintShift = vec4(0.0);
void setFootprintShift(vec4 shift) { footprintShift = shift; }
)";

// The per-pass uniforms and the outputs; names match gl_renderer.cpp.
// Everything else the tracer reads is in the parameter buffer.
constexpr std::string_view kInterface = R"(
uniform vec2 uResolution;
uniform ivec2 uSubsample;
uniform int uAA;

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outStats;
// invariant: Mesa then rounds every operation feeding the outputs exactly as
// written, instead of rewriting arithmetic (docs/toolchain-notes.md)
invariant outColor;
invariant outStats;
)";

constexpr std::string_view kMain = R"(
void main() {
    real px = gl_FragCoord.x + subsampleOffset(uSubsample.x, uAA);
    real py = gl_FragCoord.y + subsampleOffset(uSubsample.y, uAA);
    TraceState s = traceSample(px, py, uResolution.x, uResolution.y);
    outColor = vec4(s.color, 1.0);
    outStats = vec4(float(s.steps), s.hit ? 1.0 : 0.0, s.hit ? s.t : 0.0, float(s.evaluations));
}
)";

// A slot number in the text; in a fold loop's block, `stride` further per block j.
std::string slotExpression(int slot, int stride) {
    return stride == 0 ? std::to_string(slot) : std::to_string(slot) + " + " + std::to_string(stride) + " * j";
}

std::string slots(const Instruction& in, int stride) {
    std::string args;
    for (int i = 0; i < opcodeInfo(in.op).paramSlots; ++i) {
        args += ", P(" + slotExpression(in.param + i, stride) + ")";
    }
    return args;
}

std::string point(int r) { return "p" + std::to_string(r); }
std::string sample(int r) { return "s" + std::to_string(r); }

std::string formulaName(int index) { return "formula" + std::to_string(index); }

// One case per operand class (program/opcodes.h), as the CPU interpreter has.
void emitInstruction(std::ostringstream& out, const Instruction& in, int paramStride = 0, int materialStride = 0) {
    const program::OpcodeInfo& info = opcodeInfo(in.op);
    std::string fn(info.function);
    std::string material = "M(" + slotExpression(in.material, materialStride) + ")";
    std::string footprint = "footprintPoint(" + point(0) + ")";
    auto slots = [&](const Instruction& i) { return sdfwb::gl::slots(i, paramStride); };
    out << "    ";
    switch (info.opClass) {
    case OpClass::Point: out << point(in.dst) << " = " << fn << "(" << point(in.a) << slots(in) << ");\n"; break;
    case OpClass::Shape:
        out << sample(in.dst) << " = shapeSample(" << fn << "(" << point(in.a) << slots(in) << "), " << material
            << ");\n";
        break;
    case OpClass::ShapeSample:
        out << sample(in.dst) << " = " << fn << "(" << point(in.a) << ", " << footprint << slots(in) << ", " << material
            << ");\n";
        break;
    case OpClass::FormulaShape:
        out << sample(in.dst) << " = shapeSample(" << fn << "(" << formulaName(in.variant) << "(" << point(in.a)
            << ")), " << material << ");\n";
        break;
    case OpClass::FormulaSample:
        out << sample(in.dst) << " = " << fn << "(" << point(in.a) << ", " << formulaName(in.variant) << "("
            << point(in.a) << ")" << slots(in) << ", " << material << ");\n";
        break;
    case OpClass::Combine: out << sample(in.dst) << " = " << fn << "(" << sample(in.a) << ", " << sample(in.b) << ");\n"; break;
    case OpClass::SmoothCombine:
        out << sample(in.dst) << " = " << fn << "(" << sample(in.a) << ", " << sample(in.b) << slots(in) << ", "
            << in.variant << ");\n";
        break;
    case OpClass::Post:
        out << sample(in.dst) << " = " << fn << "(" << sample(in.a) << ", " << point(in.b) << slots(in) << ");\n";
        break;
    case OpClass::Texture:
    case OpClass::ImageTexture:
        out << sample(in.dst) << " = " << fn << "(" << sample(in.a) << ", " << point(in.b) << ", " << footprint
            << slots(in) << ");\n";
        break;
    case OpClass::FormulaImageTexture:
        out << sample(in.dst) << " = " << fn << "(" << sample(in.a) << ", " << point(in.b) << ", " << footprint << ", "
            << formulaName(in.variant) << "(" << point(in.b) << ")" << slots(in) << ");\n";
        break;
    case OpClass::Constant: out << sample(in.dst) << " = " << fn << "(M(MATERIAL_SLOT));\n"; break;
    }
}

}  // namespace

std::string_view vertexShaderSource() {
    return R"(#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
}

std::string_view parameterAccessSource() { return kParameters; }

std::string textureAccessSource(bool texels) {
    return std::string(texels ? kTexels : kNoTexels) + std::string(kFootprintGlobals) +
           std::string(sdf::glslTextureLookup());
}

// The fold loop's inputs: the prune grid's nodes, each leaf's (first, count)
// into the list of kept blocks, and that list (gl_renderer.cpp binds them).
constexpr std::string_view kFoldInputs = R"(
uniform isamplerBuffer uPruneNodes;
uniform isamplerBuffer uFoldSpans;
uniform isamplerBuffer uFoldBlocks;
int PN(int i) { return texelFetch(uPruneNodes, i).x; }
)";

// A run of blocks (gl/fold_run.h) as a loop over the blocks the cell of p0
// keeps, kFoldUnroll per iteration; then the outside bound where p0 is
// outside the grid (prune/prune_grid.h), as the CPU backend's leaf has it.
void emitFoldLoop(std::ostringstream& out, const program::Program& program, const FoldRun& run) {
    int grid = static_cast<int>(program.params.size()) + prune::kOutsideBoundSlots;
    out << "    int leaf = pruneLeafAt(p0, P(" << grid << "), P(" << grid + 1 << "));\n"
        << "    ivec4 span = texelFetch(uFoldSpans, leaf);\n"
        << "    for (int k = 0; k < span.y; k += " << kFoldUnroll << ") {\n";
    for (int u = 0; u < kFoldUnroll; ++u) {
        out << "    if (k + " << u << " < span.y) {\n"
            << "    int j = texelFetch(uFoldBlocks, span.x + k + " << u << ").x;\n";
        for (int i = 0; i < run.length; ++i) {
            emitInstruction(out, program.code[static_cast<size_t>(run.start + i)],
                            run.paramStride[static_cast<size_t>(i)], run.materialStride[static_cast<size_t>(i)]);
        }
        out << "    }\n";
    }
    out << "    }\n";
}

namespace {

// map(p), the field with its materials, or mapDistance(p), the same code
// returning the distances alone: the compiler then drops every material
// load and blend from it.
void emitMapFunction(std::ostringstream& out, const program::Program& program, const std::optional<FoldRun>& run,
                     bool distanceOnly) {
    out << "\nSample " << (distanceOnly ? "mapDistance" : "map") << "(vec3 p) {\n";
    out << "    vec3 p0 = p;\n";
    for (int r = 1; r < program.pointRegisters; ++r) {
        out << "    vec3 " << point(r) << ";\n";
    }
    for (int r = 0; r < program.sampleRegisters; ++r) {
        out << "    Sample " << sample(r) << ";\n";
    }
    int end = run ? run->start : static_cast<int>(program.code.size());
    for (int k = 0; k < end; ++k) {
        emitInstruction(out, program.code[static_cast<size_t>(k)]);
    }
    if (run) {
        emitFoldLoop(out, program, *run);
        for (size_t k = static_cast<size_t>(run->start + run->length * run->count); k < program.code.size(); ++k) {
            emitInstruction(out, program.code[k]);
        }
        int grid = static_cast<int>(program.params.size()) + prune::kOutsideBoundSlots;
        out << "    if (leaf == int(P(" << grid + 1 << ").w)) {\n";
        for (const Instruction& in : prune::outsideBoundCode(program)) {
            emitInstruction(out, in);
        }
        out << "    }\n";
    }
    const std::string result = sample(program.result);
    if (distanceOnly) {
        out << "    return Sample(" << result << ".d, " << result << ".step, noMaterial());\n}\n";
    } else {
        out << "    return " << result << ";\n}\n";
    }
}

}  // namespace

std::string generateMapFunction(const program::Program& program) {
    std::ostringstream out;
    for (size_t i = 0; i < program.formulas.size(); ++i) {
        out << "\n" << expr::emitGlslFunction(program.formulas[i].tape,
                                              {formulaName(static_cast<int>(i)), "vec3 p", {"p.x", "p.y", "p.z"}});
    }
    std::optional<FoldRun> run = findFoldRun(program);
    if (run) {
        out << kFoldInputs << sdf::glslPruneLookup();
    }
    emitMapFunction(out, program, run, false);
    // one call site of map(): the other driver function is a copy without
    // materials, or never called (materialSampledApart() is a constant)
    if (materialSampledApart(program)) {
        emitMapFunction(out, program, run, true);
        out << "Sample mapMaterial(vec3 p) { return map(p); }\n";
    } else {
        out << "Sample mapDistance(vec3 p) { return map(p); }\n"
            << "Sample mapMaterial(vec3 p) { return shapeSample(0.0, noMaterial()); }\n";
    }
    return out.str();
}

// Every smooth boolean of a shader is one of the program's own instructions
// (the fold loop repeats them; the prune grid's outside bound adds none), and
// a variant is part of the shader text, so this follows the structure. The
// polynomial, the dispatch's fallback, is always compiled.
std::string smoothVariantDefines(const program::Program& program) {
    std::set<int> used;
    for (const Instruction& in : program.code) {
        if (opcodeInfo(in.op).opClass == OpClass::SmoothCombine) used.insert(in.variant);
    }
    std::string defines = "#define SMOOTH_VARIANTS_OF_SCENE\n";
    for (int variant : used) {
        if (variant < 0 || variant >= static_cast<int>(std::size(scene::kSmoothVariantNames))) continue;
        std::string name(scene::kSmoothVariantNames[variant]);
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::toupper(c); });
        defines += "#define SMOOTH_USES_" + name + "\n";
    }
    return defines;
}

std::string generateFragmentShader(const program::Program& program) {
    const bool environmentMap = program.environmentKind != sdf::f32::ENVIRONMENT_COLOR;
    const bool texels = environmentMap || !program.textureFiles.empty();
    std::ostringstream out;
    out << "#version 330 core\n"
        << sdf::glslPrelude() << smoothVariantDefines(program) << sdf::glslLibrary() << kInterface
        << kParameters
        // scenes without images read no texels
        << textureAccessSource(texels) << generateMapFunction(program)
        // a constant: scenes without mirrors or glass compile no ray tree
        << "\nbool secondaryRays() { return " << (program.secondaryRays ? "true" : "false") << "; }\n"
        << "bool environmentMap() { return " << (environmentMap ? "true" : "false") << "; }\n"
        << "bool imageTextures() { return " << (program.textureFiles.empty() ? "false" : "true") << "; }\n"
        << "int materialSamplesPerHit() { return " << program.materialSamplesPerHit() << "; }\n"
        // a constant: without it the driver's loop compiles one map(), which carries the material
        << "bool materialSampledApart() { return " << (materialSampledApart(program) ? "true" : "false") << "; }\n"
        // map() and mapDistance() are fixed functions: a branch between
        // them would run both on every lane (docs/toolchain-notes.md)
        << "void setMaterialReads(int reads) {}\n"
        << sdf::glslEnvironmentLookup() << sdf::glslSampleDriver() << kMain;
    return out.str();
}

int worstCaseBackEdges(const program::Program& program) {
    const program::TraceParams& t = program.trace;
    sdf::f32::TraceSettings settings{};
    settings.maxSteps = t.maxSteps;
    settings.aoSamples = t.aoSamples;
    settings.shadowSteps = t.shadowSteps;
    settings.lightCount = static_cast<int>(program.lights.size());
    settings.maxDepth = t.maxDepth;
    static_assert(sdf::f32::RAY_TREE_ITERATION_CAP < kLoopLimiter);
    if (program.secondaryRays) {
        return sdf::f32::rayTreeIterationBound(settings);
    }
    // Split (sample_driver.glsl): the lanes' inner runs cover the march, then
    // the phases after the material, so each run stays within its phases'
    // share of the bound. Counted on top: the outer loop's passes (one a
    // material sample, one to leave) and, to be safe, one pass per inner run
    // in which every lane has already left.
    int runs = program.materialSamplesPerHit() + 1;
    int outer = materialSampledApart(program) ? 2 * runs + 1 : 0;
    return sdf::f32::traceIterationBound(settings) + outer;
}

}  // namespace sdfwb::gl
