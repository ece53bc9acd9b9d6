#include "expr/tape.h"

#include <glm/glm.hpp>

#include <cassert>

#include "sdf/shared.h"

namespace sdfwb::expr {
namespace {

// In float, the shared library's transcendental functions, which the generated
// GLSL calls too (sdf/glsl/transcendental.glsl): both backends then agree bit for
// bit. In double, the C library's, as the reference.
struct Transcendentals {
  static float sin(float a) { return sdf::f32::formulaSin(a); }
  static float cos(float a) { return sdf::f32::formulaCos(a); }
  static float tan(float a) { return sdf::f32::formulaTan(a); }
  static float exp(float a) { return sdf::f32::formulaExp(a); }
  static float log(float a) { return sdf::f32::formulaLog(a); }
  static float pow(float a, float b) { return sdf::f32::formulaPow(a, b); }
  static double sin(double a) { return glm::sin(a); }
  static double cos(double a) { return glm::cos(a); }
  static double tan(double a) { return glm::tan(a); }
  static double exp(double a) { return glm::exp(a); }
  static double log(double a) { return glm::log(a); }
  static double pow(double a, double b) { return glm::pow(a, b); }
};

// min and max with the library's rule for a NaN operand (the other one), which
// the generated GLSL's built-ins follow on llvmpipe.
float minNum(float a, float b) { return sdf::f32::min(a, b); }
double minNum(double a, double b) { return sdf::f64::min(a, b); }
float maxNum(float a, float b) { return sdf::f32::max(a, b); }
double maxNum(double a, double b) { return sdf::f64::max(a, b); }

}  // namespace

Tape::Tape(const Graph& graph, std::span<const NodeId> outputs) : variables_(graph.variables()) {
  std::vector<bool> live(graph.size(), false);
  for (NodeId o : outputs) live[o] = true;
  for (std::size_t id = graph.size(); id-- > 0;) {
    if (!live[id]) continue;
    const Node& n = graph.node(static_cast<NodeId>(id));
    for (int i = 0; i < opInfo(n.op).arity; ++i) live[n.args[i]] = true;
  }
  std::vector<std::uint32_t> slot(graph.size(), 0);
  for (std::size_t id = 0; id < graph.size(); ++id) {
    if (!live[id]) continue;
    const Node& n = graph.node(static_cast<NodeId>(id));
    Instruction in{n.op, {}, n.index};
    for (int i = 0; i < opInfo(n.op).arity; ++i) in.args[i] = slot[n.args[i]];
    if (n.op == Op::Constant) {
      in.index = static_cast<std::uint32_t>(constants_.size());
      constants_.push_back(graph.constantValues()[n.index]);
    }
    slot[id] = static_cast<std::uint32_t>(instructions_.size());
    instructions_.push_back(in);
  }
  for (NodeId o : outputs) outputs_.push_back(slot[o]);
}

template <class T>
void Tape::run(std::span<const T> variables, std::span<T> slots) const {
  assert(variables.size() == variables_.size() && slots.size() == instructions_.size());
  for (std::size_t i = 0; i < instructions_.size(); ++i) {
    const Instruction& in = instructions_[i];
    const T a = slots[in.args[0]];
    const T b = slots[in.args[1]];
    T r{};
    switch (in.op) {
      case Op::Constant: r = static_cast<T>(constants_[in.index]); break;
      case Op::Variable: r = variables[in.index]; break;
      case Op::Neg: r = -a; break;
      case Op::Add: r = a + b; break;
      case Op::Sub: r = a - b; break;
      case Op::Mul: r = a * b; break;
      case Op::Div: r = a / b; break;
      case Op::Sin: r = Transcendentals::sin(a); break;
      case Op::Cos: r = Transcendentals::cos(a); break;
      case Op::Tan: r = Transcendentals::tan(a); break;
      case Op::Exp: r = Transcendentals::exp(a); break;
      case Op::Log: r = Transcendentals::log(a); break;
      case Op::Sqrt: r = glm::sqrt(a); break;
      case Op::Abs: r = glm::abs(a); break;
      case Op::Floor: r = glm::floor(a); break;
      case Op::Min: r = minNum(a, b); break;
      case Op::Max: r = maxNum(a, b); break;
      case Op::Pow: r = Transcendentals::pow(a, b); break;
      case Op::SelectLess: r = a < b ? slots[in.args[2]] : slots[in.args[3]]; break;
      case Op::SelectEqual: r = a == b ? slots[in.args[2]] : slots[in.args[3]]; break;
    }
    slots[i] = r;
  }
}

template void Tape::run<float>(std::span<const float>, std::span<float>) const;
template void Tape::run<double>(std::span<const double>, std::span<double>) const;

}  // namespace sdfwb::expr
