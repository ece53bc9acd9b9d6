#pragma once
// Pruning a program's instructions for one cell of space: the instructions
// whose result cannot reach the scene's field anywhere in the cell are dropped,
// so the pruned list computes the same floats as the full one at every point
// of the cell (docs/large-scenes.md states the rules and when they hold).
//
// The analysis evaluates the list once at the cell's centre, in double, and
// bounds every register over the cell: a point register by its centre and a
// radius (how far the transformed point can move), a sample register by an
// interval for each of its channels (distance and safe step), from the
// Lipschitz bound of each shape and the monotonicity of every combining
// operator. A boolean whose operand provably never wins is replaced by the
// other operand; dead instructions go; registers are renamed so that a kept
// operand lands where its consumer reads.

#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "program/program.h"

namespace sdfwb::prune {

struct CodeSpan {
    std::vector<program::Instruction> code;
    int result = 0;  // sample register holding the field
};

// Instructions of `code` (a valid instruction list of `program`, reading its
// parameters and formulas) that equal the whole list for every point within
// `radius` of `centre` (march coordinates). Never longer than `code`; returns
// `code` unchanged where the analysis cannot prove a saving.
CodeSpan pruneForCell(const program::Program& program, const CodeSpan& code, const glm::dvec3& centre,
                      double radius);

// The same, keeping its working memory between cells (one per thread).
class CellPruner {
public:
    explicit CellPruner(const program::Program& program);
    ~CellPruner();
    CellPruner(const CellPruner&) = delete;
    CellPruner& operator=(const CellPruner&) = delete;

    CodeSpan prune(const CodeSpan& code, const glm::dvec3& centre, double radius);

private:
    struct Workspace;
    const program::Program& program_;
    std::unique_ptr<Workspace> workspace_;
};

}  // namespace sdfwb::prune
