#pragma once
// GLSL generation from a tape: GLSL 3.30 core built-ins only, one statement
// per instruction in the tape's order, so the shader rounds exactly the
// operations the CPU evaluator rounds: bit-identical on llvmpipe for every
// built-in. sin, cos, tan, exp, log and pow call the shared library's
// formulaSin ... formulaPow (sdf/glsl/transcendental.glsl), as the float
// evaluator does, so the shader must include sdf::glslLibrary().
//
// Bit-exactness needs one thing from the caller: declare the fragment output
// that depends on these functions `invariant` (`invariant evalResult;`, plain
// GLSL 3.30). Mesa then treats every operation feeding it as exact; without
// it, its inexact-math rules rewrite x*y + x*x as x*(y + x) and results
// differ by an ulp (measured on llvmpipe, Mesa 22.3).

#include <string>
#include <vector>

#include "expr/tape.h"

namespace sdfwb::expr {

struct GlslFunction {
  std::string name;        // e.g. "sdUser0"
  std::string parameters;  // the parameter list, e.g. "vec3 p"
  // A GLSL expression for each tape variable, e.g. {"p.x", "p.y", "p.z"}.
  std::vector<std::string> variables;
};

// A float constant as a GLSL literal that parses back to the same float as
// float(value) in C++ (9 significant digits, always with '.' or an exponent;
// negative ones parenthesized; infinities through uintBitsToFloat).
std::string glslFloatLiteral(double value);

// The function's statements without braces: `float tN = ...;` lines, then
// `return` of a float (one output) or a vec2/vec3/vec4 of the outputs in order.
std::string emitGlslBody(const Tape& tape, const std::vector<std::string>& variables);

// A whole function definition: "<float|vecN> name(parameters) {\n body }\n".
// Requires 1 to 4 outputs.
std::string emitGlslFunction(const Tape& tape, const GlslFunction& function);

}  // namespace sdfwb::expr
