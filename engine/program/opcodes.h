#pragma once
// The compiled scene's instruction set. Each opcode names the shared-library
// function both backends call for it (sdf/glsl/instructions.glsl). The list
// below is the only place an opcode is typed: the enum, the info table, the
// GLSL generator's calls and the CPU interpreter's dispatch are all expanded
// from it, so a new opcode cannot reach one backend and miss the other.

#include <array>
#include <string_view>

namespace sdfwb::program {

// How an instruction's operands and result are wired; the generator and the
// interpreter each have one case per class, never one per opcode. F is
// footprintPoint(P[0]), the point footprints are measured from: the march
// point (the eye at 0) unfolded along the ray's path from the eye
// (sdf/glsl/footprint_point.glsl).
enum class OpClass {
    Point,                // P[dst] = f(P[a], slots)
    Shape,                // S[dst] = shapeSample(f(P[a], slots), material)
    ShapeSample,          // S[dst] = f(P[a], F, slots, material)
    FormulaShape,         // S[dst] = shapeSample(f(formula value at P[a]), material)
    FormulaSample,        // S[dst] = f(P[a], formula value and gradient at P[a], slots, material)
    Combine,              // S[dst] = f(S[a], S[b])
    SmoothCombine,        // S[dst] = f(S[a], S[b], slots, variant)
    Post,                 // S[dst] = f(S[a], P[b], slots)
    Texture,              // S[dst] = f(S[a], P[b], F, slots)
    ImageTexture,         // as Texture, and f reads the backend's texel buffer (sdf/glsl/texture_lookup.glsl)
    FormulaImageTexture,  // S[dst] = f(S[a], P[b], F, formula value and gradient at P[b], slots), reads texels
    Constant,             // S[dst] = f(default material): "nothing here"
};

// A primitive (its result carries a shape's material), and a boolean of two samples.
constexpr bool isShapeClass(OpClass c) {
    return c == OpClass::Shape || c == OpClass::ShapeSample || c == OpClass::FormulaShape ||
           c == OpClass::FormulaSample;
}
constexpr bool isCombineClass(OpClass c) { return c == OpClass::Combine || c == OpClass::SmoothCombine; }

// X(Enum, name, class, parameter slots, shared function). Parameter layouts are
// documented beside each function in instructions.glsl. Formula opcodes take
// Program::formulas[Instruction::variant].
#define SDFWB_OPCODES(X)                                                                   \
    X(Translate, "translate", Point, 1, instTranslate)                                     \
    X(Rotate, "rotate", Point, 3, instRotate)                                              \
    X(Scale, "scale", Point, 1, instScale)                                                 \
    X(Twist, "twist", Point, 1, instTwist)                                                 \
    X(Bend, "bend", Point, 1, instBend)                                                    \
    X(Elongate, "elongate", Point, 1, instElongate)                                        \
    X(Mirror, "mirror", Point, 1, instMirror)                                              \
    X(Repeat, "repeat", Point, 2, instRepeat)                                              \
    X(RepeatInfinite, "repeat_infinite", Point, 1, instRepeatInfinite)                     \
    X(Sphere, "sphere", Shape, 1, instSphere)                                              \
    X(Box, "box", Shape, 1, instBox)                                                       \
    X(RoundBox, "round_box", Shape, 1, instRoundBox)                                       \
    X(Plane, "plane", Shape, 1, instPlane)                                                 \
    X(Torus, "torus", Shape, 1, instTorus)                                                 \
    X(Cone, "cone", Shape, 1, instCone)                                                    \
    X(Ellipsoid, "ellipsoid", Shape, 1, instEllipsoid)                                     \
    X(Cylinder, "cylinder", Shape, 1, instCylinder)                                        \
    X(Capsule, "capsule", Shape, 2, instCapsule)                                           \
    X(Ground, "ground", ShapeSample, 3, instGround)                                        \
    X(SdfFormula, "sdf_formula", FormulaShape, 0, instSdfFormula)                          \
    X(ImplicitFormula, "implicit_formula", FormulaSample, 2, instImplicit)                 \
    X(Union, "union", Combine, 0, instUnion)                                               \
    X(Intersection, "intersection", Combine, 0, instIntersection)                          \
    X(Difference, "difference", Combine, 0, instDifference)                                \
    X(SmoothUnion, "smooth_union", SmoothCombine, 1, instSmoothUnion)                      \
    X(SmoothIntersection, "smooth_intersection", SmoothCombine, 1, instSmoothIntersection) \
    X(SmoothDifference, "smooth_difference", SmoothCombine, 1, instSmoothDifference)       \
    X(ScaleDistance, "scale_distance", Post, 1, instScaleDistance)                         \
    X(RoundDistance, "round_distance", Post, 1, instRoundDistance)                         \
    X(Displace, "displace", Post, 1, instDisplace)                                         \
    X(StepScale, "step_scale", Post, 1, instStepScale)                                     \
    X(Texture, "texture", Texture, 2, instTexture)                                         \
    X(ImageTexture, "image_texture", ImageTexture, 4, instImageTexture)                    \
    X(TriplanarTexture, "triplanar_texture", FormulaImageTexture, 2, instTriplanarTexture) \
    X(Bump, "bump", Texture, 1, instBump)                                                  \
    X(Empty, "empty", Constant, 0, instEmpty)

enum class Opcode {
#define SDFWB_OPCODE_ENUM(op, name, cls, slots, fn) op,
    SDFWB_OPCODES(SDFWB_OPCODE_ENUM)
#undef SDFWB_OPCODE_ENUM
};
inline constexpr int kOpcodeCount = 0
#define SDFWB_OPCODE_COUNT(op, name, cls, slots, fn) +1
    SDFWB_OPCODES(SDFWB_OPCODE_COUNT)
#undef SDFWB_OPCODE_COUNT
    ;

struct OpcodeInfo {
    Opcode op;
    std::string_view name;
    OpClass opClass;
    int paramSlots;            // vec4 slots read from the parameter buffer
    std::string_view function; // the shared-library function (sdf/glsl/instructions.glsl)
};

inline constexpr std::array<OpcodeInfo, kOpcodeCount> kOpcodes = {{
#define SDFWB_OPCODE_INFO(op, name, cls, slots, fn) {Opcode::op, name, OpClass::cls, slots, #fn},
    SDFWB_OPCODES(SDFWB_OPCODE_INFO)
#undef SDFWB_OPCODE_INFO
}};

constexpr const OpcodeInfo& opcodeInfo(Opcode op) { return kOpcodes[static_cast<size_t>(op)]; }

}  // namespace sdfwb::program
