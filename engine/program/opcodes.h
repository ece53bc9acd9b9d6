#pragma once
// The compiled scene's instruction set. Each opcode names the shared-library
// function both backends call for it (the GLSL generator emits that call, the CPU
// evaluator makes it), so the table below is the single list of operations.

#include <array>
#include <string_view>

namespace sdfwb::program {

enum class OpClass {
    Point,    // P[dst] = f(P[a], params)
    Shape,    // S[dst] = Sample(f(P[a], params), material); Ground returns the Sample itself
    Combine,  // S[dst] = f(S[a], S[b], params)
    Post,     // S[dst] = f(S[a], P[b], params)
    Constant, // S[dst] = nothing here: distance "far", default material
};

enum class Opcode {
    Translate, Rotate, Scale, Twist, Bend, Elongate, Mirror, Repeat, RepeatInfinite,
    Sphere, Box, RoundBox, Plane, Torus, Cone, Ellipsoid, Cylinder, Capsule, Ground,
    SdfFormula, ImplicitFormula,
    Union, Intersection, Difference, SmoothUnion, SmoothIntersection, SmoothDifference,
    ScaleDistance, RoundDistance, Displace, StepScale,
    Empty,
};
inline constexpr int kOpcodeCount = static_cast<int>(Opcode::Empty) + 1;

struct OpcodeInfo {
    Opcode op;
    std::string_view name;
    OpClass opClass;
    int paramSlots;            // vec4 slots read from the parameter buffer
    std::string_view function; // the shared-library function (sdf/glsl/instructions.glsl)
};

inline constexpr std::array<OpcodeInfo, kOpcodeCount> kOpcodes = {{
    {Opcode::Translate, "translate", OpClass::Point, 1, "instTranslate"},
    {Opcode::Rotate, "rotate", OpClass::Point, 3, "instRotate"},
    {Opcode::Scale, "scale", OpClass::Point, 1, "instScale"},
    {Opcode::Twist, "twist", OpClass::Point, 1, "instTwist"},
    {Opcode::Bend, "bend", OpClass::Point, 1, "instBend"},
    {Opcode::Elongate, "elongate", OpClass::Point, 1, "instElongate"},
    {Opcode::Mirror, "mirror", OpClass::Point, 1, "instMirror"},
    {Opcode::Repeat, "repeat", OpClass::Point, 2, "instRepeat"},
    {Opcode::RepeatInfinite, "repeat_infinite", OpClass::Point, 1, "instRepeatInfinite"},
    {Opcode::Sphere, "sphere", OpClass::Shape, 1, "instSphere"},
    {Opcode::Box, "box", OpClass::Shape, 1, "instBox"},
    {Opcode::RoundBox, "round_box", OpClass::Shape, 1, "instRoundBox"},
    {Opcode::Plane, "plane", OpClass::Shape, 1, "instPlane"},
    {Opcode::Torus, "torus", OpClass::Shape, 1, "instTorus"},
    {Opcode::Cone, "cone", OpClass::Shape, 1, "instCone"},
    {Opcode::Ellipsoid, "ellipsoid", OpClass::Shape, 1, "instEllipsoid"},
    {Opcode::Cylinder, "cylinder", OpClass::Shape, 1, "instCylinder"},
    {Opcode::Capsule, "capsule", OpClass::Shape, 2, "instCapsule"},
    {Opcode::Ground, "ground", OpClass::Shape, 3, "instGround"},
    // Formula shapes: Instruction::variant indexes Program::formulas
    {Opcode::SdfFormula, "sdf_formula", OpClass::Shape, 0, "instSdfFormula"},
    {Opcode::ImplicitFormula, "implicit_formula", OpClass::Shape, 2, "instImplicit"},
    {Opcode::Union, "union", OpClass::Combine, 0, "instUnion"},
    {Opcode::Intersection, "intersection", OpClass::Combine, 0, "instIntersection"},
    {Opcode::Difference, "difference", OpClass::Combine, 0, "instDifference"},
    {Opcode::SmoothUnion, "smooth_union", OpClass::Combine, 1, "instSmoothUnion"},
    {Opcode::SmoothIntersection, "smooth_intersection", OpClass::Combine, 1, "instSmoothIntersection"},
    {Opcode::SmoothDifference, "smooth_difference", OpClass::Combine, 1, "instSmoothDifference"},
    {Opcode::ScaleDistance, "scale_distance", OpClass::Post, 1, "instScaleDistance"},
    {Opcode::RoundDistance, "round_distance", OpClass::Post, 1, "instRoundDistance"},
    {Opcode::Displace, "displace", OpClass::Post, 1, "instDisplace"},
    {Opcode::StepScale, "step_scale", OpClass::Post, 1, "instStepScale"},
    {Opcode::Empty, "empty", OpClass::Constant, 0, "instEmpty"},
}};

constexpr const OpcodeInfo& opcodeInfo(Opcode op) { return kOpcodes[static_cast<size_t>(op)]; }

static_assert([] {
    for (int i = 0; i < kOpcodeCount; ++i) {
        if (static_cast<int>(kOpcodes[static_cast<size_t>(i)].op) != i) {
            return false;
        }
    }
    return true;
}(), "kOpcodes must list every opcode in enum order");

}  // namespace sdfwb::program
