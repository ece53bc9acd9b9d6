#include "gl/program_size.h"

namespace sdfwb::gl {

std::size_t shaderStatementCount(const program::Program& program) {
    std::size_t count = program.code.size();
    for (const program::FormulaCode& formula : program.formulas) {
        count += formula.tape.instructions().size();
    }
    return count;
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
