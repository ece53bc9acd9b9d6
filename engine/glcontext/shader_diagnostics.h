#pragma once
// Shader compiler and linker messages tied to the lines of the source they
// came from, so a report can show the offending line of generated code.

#include <GL/glcorearb.h>

#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::glcontext {

struct ShaderDiagnostic {
  GLenum stage = 0;     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...; 0 for the link step
  int line = 0;         // 1-based line in the shader's source; 0 if the message has none
  int column = 0;       // 1-based column as the driver counts it, 0 if none; Mesa counts in
                        // preprocessed text, where whitespace and comment runs are one space
  std::string message;  // the driver's text after the location, e.g. "error: `foo' undeclared"
};

// Splits an info log into one diagnostic per message line, each marked with
// `stage`. Understands
// Mesa's "0:12(5): error: ..." (llvmpipe), NVIDIA's "0(12) : error C1008: ..."
// and the "ERROR: 0:12: ..." form of other drivers; any other line is kept
// whole with line 0. Blank lines are dropped.
std::vector<ShaderDiagnostic> parseInfoLog(std::string_view log, GLenum stage);

// Formats diagnostics for a person, one block per message: the location and
// message, then the source line it points at (from `source`) with a caret
// under the column when there is one:
//   fragment shader:12:5: error: `foo' undeclared
//      12 |   float d = foo(p);
//         |             ^
// `what` names the shader ("fragment shader"); messages without a line are
// printed after "what: ". Consecutive messages on one line share one echo.
std::string formatDiagnostics(std::string_view what, std::string_view source,
                              const std::vector<ShaderDiagnostic>& diagnostics);

}  // namespace sdfwb::glcontext
