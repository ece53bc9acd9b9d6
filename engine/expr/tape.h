#pragma once
// The compact evaluation form shared by the CPU evaluator and the GLSL
// generator: the nodes the outputs need, in one fixed order. Both backends
// walk the same instructions, so they round the same operations the same way.

#include <cstdint>
#include <span>
#include <vector>

#include "expr/graph.h"

namespace sdfwb::expr {

class Tape {
 public:
  struct Instruction {
    Op op;
    std::array<std::uint32_t, 4> args;  // operand slots (earlier instructions)
    std::uint32_t index;                // Constant: into constants(); Variable: variable number
  };

  // The nodes reachable from `outputs`, renumbered densely in graph order.
  Tape(const Graph& graph, std::span<const NodeId> outputs);

  std::span<const Instruction> instructions() const { return instructions_; }
  std::span<const double> constants() const { return constants_; }
  // The slot of each output, in the order given.
  std::span<const std::uint32_t> outputs() const { return outputs_; }
  // Names of the graph's variables; an evaluation needs a value for each.
  const std::vector<std::string>& variables() const { return variables_; }

  // Runs every instruction: slots[i] receives instruction i's value. T is float
  // or double; constants are the correctly rounded doubles converted to T.
  // Requires variables.size() == variables().size() and slots.size() == instructions().size().
  template <class T>
  void run(std::span<const T> variables, std::span<T> slots) const;

 private:
  std::vector<Instruction> instructions_;
  std::vector<double> constants_;
  std::vector<std::uint32_t> outputs_;
  std::vector<std::string> variables_;
};

// Evaluates a tape's outputs with a scratch buffer of its own (one per thread).
template <class T>
class Evaluator {
 public:
  explicit Evaluator(const Tape& tape) : tape_(&tape), slots_(tape.instructions().size()) {}

  // The outputs, in the tape's order; valid until the next call.
  std::span<const T> operator()(std::span<const T> variables) {
    tape_->run<T>(variables, slots_);
    outputs_.resize(tape_->outputs().size());
    for (std::size_t i = 0; i < outputs_.size(); ++i) outputs_[i] = slots_[tape_->outputs()[i]];
    return outputs_;
  }

 private:
  const Tape* tape_;
  std::vector<T> slots_;
  std::vector<T> outputs_;
};

}  // namespace sdfwb::expr
