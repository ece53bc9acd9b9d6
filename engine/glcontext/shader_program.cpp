#include "glcontext/shader_program.h"

namespace sdfwb::glcontext {

namespace {

// The info log of a shader (GetShaderiv, GetShaderInfoLog) or a program
// (GetProgramiv, GetProgramInfoLog).
template <auto GlFunctions::*GetParameter, auto GlFunctions::*GetLog>
std::string infoLog(const GlFunctions& gl, GLuint object) {
  GLint length = 0;
  (gl.*GetParameter)(object, GL_INFO_LOG_LENGTH, &length);
  if (length <= 0) return {};
  std::string log(static_cast<std::size_t>(length), '\0');
  GLsizei written = 0;
  (gl.*GetLog)(object, length, &written, log.data());
  log.resize(static_cast<std::size_t>(written));
  return log;
}

// Adds one step's messages to the build, formatted against its source.
void record(ProgramBuild& build, std::string_view what, GLenum stage, std::string_view source,
            std::string_view log) {
  std::vector<ShaderDiagnostic> diagnostics = parseInfoLog(log, stage);
  build.report += formatDiagnostics(what, source, diagnostics);
  build.diagnostics.insert(build.diagnostics.end(), diagnostics.begin(), diagnostics.end());
}

}  // namespace

std::string_view stageName(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex shader";
    case GL_FRAGMENT_SHADER: return "fragment shader";
    case GL_GEOMETRY_SHADER: return "geometry shader";
    default: return "shader";
  }
}

ProgramBuild buildProgram(const GlFunctions& gl, std::span<const ShaderSource> stages,
                          std::string_view label) {
  ProgramBuild build;
  std::vector<GlObject> shaders;
  std::string failedStep;
  for (const ShaderSource& source : stages) {
    std::string what = std::string(label) + " " + std::string(stageName(source.stage));
    GlObject shader = adoptShader(gl, gl.CreateShader(source.stage));
    if (!shader) {
      failedStep = "could not create the " + std::string(stageName(source.stage));
      break;
    }
    const GLchar* text = source.text.data();
    const GLint length = static_cast<GLint>(source.text.size());
    gl.ShaderSource(shader.get(), 1, &text, &length);
    gl.CompileShader(shader.get());
    GLint compiled = GL_FALSE;
    gl.GetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
    record(build, what, source.stage, source.text,
           infoLog<&GlFunctions::GetShaderiv, &GlFunctions::GetShaderInfoLog>(gl, shader.get()));
    if (!compiled && failedStep.empty()) {
      failedStep = "the " + std::string(stageName(source.stage)) + " did not compile";
    }
    shaders.push_back(std::move(shader));
  }

  if (failedStep.empty()) {
    GlObject program = adoptProgram(gl, gl.CreateProgram());
    if (!program) {
      failedStep = "could not create a program object";
    } else {
      for (const GlObject& shader : shaders) gl.AttachShader(program.get(), shader.get());
      gl.LinkProgram(program.get());
      // Detached shaders are deleted with their GlObject; the program keeps
      // its linked code.
      for (const GlObject& shader : shaders) gl.DetachShader(program.get(), shader.get());
      GLint linked = GL_FALSE;
      gl.GetProgramiv(program.get(), GL_LINK_STATUS, &linked);
      record(build, std::string(label) + " link", 0, {},
             infoLog<&GlFunctions::GetProgramiv, &GlFunctions::GetProgramInfoLog>(gl, program.get()));
      if (linked) {
        build.program = std::move(program);
      } else {
        failedStep = "the program did not link";
      }
    }
  }

  if (!failedStep.empty()) build.report += std::string(label) + ": " + failedStep + "\n";
  return build;
}

}  // namespace sdfwb::glcontext

