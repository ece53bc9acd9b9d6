#pragma once
// Compiling and linking GLSL programs with reports a person can act on.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"
#include "glcontext/shader_diagnostics.h"

namespace sdfwb::glcontext {

struct ShaderSource {
  GLenum stage;           // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string_view text;  // the complete source, from its #version line
};

struct ProgramBuild {
  GlObject program;                           // the linked program; empty if the build failed
  std::vector<ShaderDiagnostic> diagnostics;  // every compile and link message, warnings included
  // The diagnostics formatted by formatDiagnostics (each located message
  // followed by its source line), plus a line saying which step failed.
  // Empty when everything built without a message.
  std::string report;

  bool ok() const { return static_cast<bool>(program); }
};

// "vertex shader", "fragment shader", "geometry shader", or "shader".
std::string_view stageName(GLenum stage);

// Compiles each stage and links them into a program, in the context current
// on this thread. Never throws for bad GLSL and never aborts: a failure
// comes back as an empty program and a report whose lines read
// "<label> fragment shader:12:5: error: ...", line numbers counting lines of
// the given text. The link step runs only when every stage compiled.
ProgramBuild buildProgram(const GlFunctions& gl, std::span<const ShaderSource> stages,
                          std::string_view label);

}  // namespace sdfwb::glcontext
