#include "expr/glsl.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sdfwb::expr {
namespace {

std::string returnType(std::size_t outputs) {
  if (outputs == 1) return "float";
  return "vec" + std::to_string(outputs);
}

// The transcendental built-ins come from the shared library
// (sdf/glsl/transcendental.glsl), as in the float evaluator: llvmpipe's own
// differ from the C library's in the last bits.
std::string_view glslFunctionName(Op op) {
  switch (op) {
    case Op::Sin: return "formulaSin";
    case Op::Cos: return "formulaCos";
    case Op::Tan: return "formulaTan";
    case Op::Exp: return "formulaExp";
    case Op::Log: return "formulaLog";
    case Op::Pow: return "formulaPow";
    default: return opInfo(op).name;
  }
}

}  // namespace

std::string glslFloatLiteral(double value) {
  const float f = static_cast<float>(value);
  if (std::isinf(f)) return f > 0 ? "uintBitsToFloat(0x7f800000u)" : "uintBitsToFloat(0xff800000u)";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(f));
  std::string text = buffer;
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return f < 0 || std::signbit(f) ? "(" + text + ")" : text;
}

std::string emitGlslBody(const Tape& tape, const std::vector<std::string>& variables) {
  if (variables.size() != tape.variables().size()) {
    throw std::invalid_argument("emitGlslBody: expected " + std::to_string(tape.variables().size()) +
                                " variable expressions, got " + std::to_string(variables.size()));
  }
  const auto instructions = tape.instructions();
  // What each slot is called in the code: a literal, a variable, or a temporary.
  std::vector<std::string> names(instructions.size());
  std::string body;
  int temporaries = 0;
  for (std::size_t i = 0; i < instructions.size(); ++i) {
    const Tape::Instruction& in = instructions[i];
    const std::string& a = names[in.args[0]];
    const std::string& b = names[in.args[1]];
    std::string value;
    switch (in.op) {
      case Op::Constant: names[i] = glslFloatLiteral(tape.constants()[in.index]); continue;
      case Op::Variable: names[i] = variables[in.index]; continue;
      case Op::Neg: value = "-" + a; break;
      case Op::Add: value = a + " + " + b; break;
      case Op::Sub: value = a + " - " + b; break;
      case Op::Mul: value = a + " * " + b; break;
      case Op::Div: value = a + " / " + b; break;
      case Op::SelectLess:
        value = a + " < " + b + " ? " + names[in.args[2]] + " : " + names[in.args[3]];
        break;
      case Op::SelectEqual:
        value = a + " == " + b + " ? " + names[in.args[2]] + " : " + names[in.args[3]];
        break;
      default: {
        const int arity = opInfo(in.op).arity;
        value = std::string(glslFunctionName(in.op)) + "(" + a + (arity == 2 ? ", " + b : "") + ")";
        break;
      }
    }
    names[i] = "t" + std::to_string(temporaries++);
    body += "  float " + names[i] + " = " + value + ";\n";
  }
  const auto outputs = tape.outputs();
  std::string result = outputs.size() == 1 ? names[outputs[0]] : returnType(outputs.size()) + "(";
  if (outputs.size() > 1) {
    for (std::size_t i = 0; i < outputs.size(); ++i) result += (i ? ", " : "") + names[outputs[i]];
    result += ")";
  }
  return body + "  return " + result + ";\n";
}

std::string emitGlslFunction(const Tape& tape, const GlslFunction& function) {
  const std::size_t outputs = tape.outputs().size();
  if (outputs < 1 || outputs > 4) throw std::invalid_argument("emitGlslFunction: needs 1 to 4 outputs");
  return returnType(outputs) + " " + function.name + "(" + function.parameters + ") {\n" +
         emitGlslBody(tape, function.variables) + "}\n";
}

}  // namespace sdfwb::expr
