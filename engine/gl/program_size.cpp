#include "gl/program_size.h"

#include <optional>

#include "gl/fold_run.h"

namespace sdfwb::gl {

std::size_t shaderStatementCount(const program::Program& program) {
    std::size_t count = program.code.size();
    if (std::optional<FoldRun> run = findFoldRun(program)) {
        // the run's blocks become one loop body of kFoldUnroll blocks, plus the outside bound
        count = count - static_cast<std::size_t>(run->length * run->count) +
                static_cast<std::size_t>(run->length * kFoldUnroll) + prune::outsideBoundCode(program).size();
    }
    for (const program::FormulaCode& formula : program.formulas) {
        count += formula.tape.instructions().size();
    }
    return count;
}

bool materialSampledApart(const program::Program& program) {
    return program.materialPhaseApart() && 2 * shaderStatementCount(program) <= kMaxShaderStatements;
}

std::string shaderSizeProblem(const program::Program& program) {
    const std::size_t count = shaderStatementCount(program);
    if (count <= kMaxShaderStatements) {
        return "";
    }
    return "the scene makes a shader of " + std::to_string(count) + " statements (the GL backend takes at most " +
           std::to_string(kMaxShaderStatements) + ", larger ones compile for minutes): render it with the CPU backend";
}

}  // namespace sdfwb::gl
