#pragma once
// How large a shader a program makes, known before generating or compiling
// it: llvmpipe's compile time grows faster than the shader (thousands of scene
// nodes take minutes and gigabytes), so an over-large program is refused with
// a message instead of freezing the caller.

#include <cstddef>
#include <string>

#include "program/program.h"

namespace sdfwb::gl {

// Statements of the generated map(): one per scene instruction (a fold run's
// blocks counted once per unrolled copy, gl/fold_run.h) and one per formula
// tape instruction.
std::size_t shaderStatementCount(const program::Program& program);

// Above this the GL backend refuses a program (measured on llvmpipe:
// docs/toolchain-notes.md, "GL compile time and program size").
inline constexpr std::size_t kMaxShaderStatements = 1500;

// Whether the fragment shader takes the material phase's evaluations apart
// (Program::materialPhaseApart) with its map() fitting the size bound twice,
// as the distance-only mapDistance() the others run is a second copy of it.
bool materialSampledApart(const program::Program& program);

// "" when the program fits, else one line naming the size and the way out.
std::string shaderSizeProblem(const program::Program& program);

}  // namespace sdfwb::gl
