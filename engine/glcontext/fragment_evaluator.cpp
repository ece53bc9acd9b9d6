#include "glcontext/fragment_evaluator.h"

#include <array>

#include "glcontext/gl_debug.h"
#include "glcontext/gl_error.h"
#include "glcontext/shader_program.h"

namespace sdfwb::glcontext {

namespace {

constexpr std::string_view kPrelude = R"(#version 330 core
// FragmentEvaluator prelude: main() runs once per output pixel.
uniform ivec2 evalOutputSize;
layout(location = 0) out vec4 evalResult;
ivec2 evalPixel() { return ivec2(gl_FragCoord.xy); }
int evalIndex() { ivec2 pixel = evalPixel(); return pixel.y * evalOutputSize.x + pixel.x; }
)";

// One triangle over the whole viewport, (-1,-1) (3,-1) (-1,3), made from
// gl_VertexID: no vertex buffer, and no diagonal seam as with two triangles.
constexpr std::string_view kVertexShader = R"(#version 330 core
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}
)";

struct TexelFormat {
  GLenum internalFormat;
  GLenum pixelFormat;
};

TexelFormat texelFormat(const EvaluatorInput& input) {
  switch (input.components) {
    case 1: return {GL_R32F, GL_RED};
    case 2: return {GL_RG32F, GL_RG};
    case 4: return {GL_RGBA32F, GL_RGBA};
    default:
      throw GlError("FragmentEvaluator input '" + input.sampler + "': " +
                    std::to_string(input.components) + " components per texel; use 1, 2 or 4");
  }
}

GLint glInteger(const GlFunctions& gl, GLenum name) {
  GLint value = 0;
  gl.GetIntegerv(name, &value);
  return value;
}

// The program's sampler uniform for `input`, checked to exist with the type
// its layout needs; returns its location.
GLint samplerLocation(const GlFunctions& gl, GLuint program, const EvaluatorInput& input) {
  const bool buffer = input.layout == InputLayout::Buffer;
  const char* declaration = buffer ? "uniform samplerBuffer " : "uniform sampler2D ";
  const GLchar* name = input.sampler.c_str();
  GLuint index = GL_INVALID_INDEX;
  gl.GetUniformIndices(program, 1, &name, &index);
  if (index == GL_INVALID_INDEX) {
    throw GlError("FragmentEvaluator input '" + input.sampler +
                  "': the shader has no active uniform of that name (misspelt, or unused and "
                  "optimised away); declare and read `" + declaration + input.sampler + ";`");
  }
  GLint type = 0;
  gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_TYPE, &type);
  if (type != (buffer ? GL_SAMPLER_BUFFER : GL_SAMPLER_2D)) {
    throw GlError("FragmentEvaluator input '" + input.sampler + "': a " +
                  (buffer ? "Buffer" : "PerPixel") + " input needs `" + declaration +
                  input.sampler + ";` in the shader");
  }
  return gl.GetUniformLocation(program, name);
}

// The GL objects holding one input while it is bound.
struct BoundInput {
  GlObject texture;
  GlObject buffer;  // Buffer layout only
};

BoundInput bindInput(const GlFunctions& gl, GLuint program, const EvaluatorInput& input, GLuint unit,
                     int width, int height) {
  const TexelFormat format = texelFormat(input);
  const std::size_t components = static_cast<std::size_t>(input.components);
  if (input.values.empty() || input.values.size() % components != 0) {
    throw GlError("FragmentEvaluator input '" + input.sampler + "': " +
                  std::to_string(input.values.size()) + " values is not a positive multiple of " +
                  std::to_string(components) + " components");
  }
  const std::size_t texels = input.values.size() / components;
  const GLint location = samplerLocation(gl, program, input);

  BoundInput bound{makeTexture(gl), {}};
  gl.ActiveTexture(GL_TEXTURE0 + unit);
  if (input.layout == InputLayout::Buffer) {
    const auto maxTexels = static_cast<std::size_t>(glInteger(gl, GL_MAX_TEXTURE_BUFFER_SIZE));
    if (texels > maxTexels) {
      throw GlError("FragmentEvaluator input '" + input.sampler + "': " + std::to_string(texels) +
                    " texels exceed GL_MAX_TEXTURE_BUFFER_SIZE (" + std::to_string(maxTexels) + ")");
    }
    bound.buffer = makeBuffer(gl);
    gl.BindBuffer(GL_TEXTURE_BUFFER, bound.buffer.get());
    gl.BufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(input.values.size() * sizeof(float)),
                  input.values.data(), GL_STATIC_DRAW);
    gl.BindBuffer(GL_TEXTURE_BUFFER, 0);
    gl.BindTexture(GL_TEXTURE_BUFFER, bound.texture.get());
    gl.TexBuffer(GL_TEXTURE_BUFFER, format.internalFormat, bound.buffer.get());
  } else {
    if (texels != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
      throw GlError("FragmentEvaluator input '" + input.sampler + "': a PerPixel input needs " +
                    std::to_string(width) + "x" + std::to_string(height) + " texels, got " +
                    std::to_string(texels));
    }
    gl.BindTexture(GL_TEXTURE_2D, bound.texture.get());
    // Without mipmaps the default minification filter leaves the texture
    // incomplete, and texelFetch on an incomplete texture returns zeros.
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // Rows of one-float texels are 4·W bytes: any alignment above 4 would
    // skew them.
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(format.internalFormat), width, height, 0,
                  format.pixelFormat, GL_FLOAT, input.values.data());
  }
  gl.Uniform1i(location, static_cast<GLint>(unit));
  return bound;
}

// A W×H RGBA32F colour target.
struct Target {
  GlObject texture;
  GlObject framebuffer;
};

Target makeTarget(const GlFunctions& gl, int width, int height) {
  Target target{makeTexture(gl), makeFramebuffer(gl)};
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, target.texture.get());
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.get());
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.get(), 0);
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  gl.DrawBuffers(1, &drawBuffer);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    throw GlError("FragmentEvaluator: the RGBA32F framebuffer is incomplete (status " +
                  glErrorName(status) + ")");
  }
  return target;
}

void unbindAll(const GlFunctions& gl, std::size_t inputCount) {
  for (std::size_t unit = 0; unit < inputCount; ++unit) {
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    gl.BindTexture(GL_TEXTURE_BUFFER, 0);
    gl.BindTexture(GL_TEXTURE_2D, 0);
  }
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindVertexArray(0);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.UseProgram(0);
}

}  // namespace

std::string_view FragmentEvaluator::prelude() { return kPrelude; }

FragmentEvaluator::FragmentEvaluator(const GlFunctions& gl, std::string_view source)
    : fragmentSource_(std::string(kPrelude) + std::string(source)) {
  const std::array<ShaderSource, 2> stages = {{
      {GL_VERTEX_SHADER, kVertexShader},
      {GL_FRAGMENT_SHADER, fragmentSource_},
  }};
  ProgramBuild build = buildProgram(gl, stages, "FragmentEvaluator");
  if (!build.ok()) throw GlError(build.report);
  program_ = std::move(build.program);
}

std::vector<float> FragmentEvaluator::evaluate(const GlFunctions& gl, int width, int height,
                                               std::span<const EvaluatorInput> inputs) const {
  const GLint maxSize = glInteger(gl, GL_MAX_TEXTURE_SIZE);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize) {
    throw GlError("FragmentEvaluator: output size " + std::to_string(width) + "x" +
                  std::to_string(height) + " is outside 1.." + std::to_string(maxSize) + " per side");
  }
  const GLint maxUnits = glInteger(gl, GL_MAX_TEXTURE_IMAGE_UNITS);
  if (inputs.size() > static_cast<std::size_t>(maxUnits)) {
    throw GlError("FragmentEvaluator: " + std::to_string(inputs.size()) +
                  " inputs exceed GL_MAX_TEXTURE_IMAGE_UNITS (" + std::to_string(maxUnits) + ")");
  }

  std::vector<float> result(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  try {
    // The target first: making it uses texture unit 0, where an input may go.
    Target target = makeTarget(gl, width, height);
    gl.UseProgram(program_.get());
    std::vector<BoundInput> bound;
    for (std::size_t unit = 0; unit < inputs.size(); ++unit) {
      bound.push_back(bindInput(gl, program_.get(), inputs[unit], static_cast<GLuint>(unit), width, height));
    }
    gl.Uniform2i(gl.GetUniformLocation(program_.get(), "evalOutputSize"), width, height);

    GlObject vertexArray = makeVertexArray(gl);  // core profile draws need one bound
    gl.BindVertexArray(vertexArray.get());
    // Every pixel must receive exactly what main() wrote.
    gl.Disable(GL_BLEND);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_STENCIL_TEST);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Viewport(0, 0, width, height);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    // Float targets are read unclamped (GL_CLAMP_READ_COLOR is
    // GL_FIXED_ONLY in core profiles); RGBA float rows are always aligned.
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.data());
    unbindAll(gl, inputs.size());
  } catch (...) {
    unbindAll(gl, inputs.size());
    throw;
  }
  checkGlError(gl, "FragmentEvaluator::evaluate");
  return result;
}

}  // namespace sdfwb::glcontext
