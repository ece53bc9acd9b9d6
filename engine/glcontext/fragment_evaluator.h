#pragma once
// Runs a fragment shader once per pixel of a W×H RGBA32F target and reads
// the floats back: GLSL as a calculator. Used to compare GLSL functions with
// their C++ twins on the same inputs, and by the GLSL backend.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "glcontext/gl_functions.h"
#include "glcontext/gl_object.h"

namespace sdfwb::glcontext {

// How an input reaches the shader.
enum class InputLayout {
  Buffer,    // a buffer texture of any length: `uniform samplerBuffer name;`,
             // read with texelFetch(name, evalIndex())
  PerPixel,  // a W×H float texture, one texel per output pixel:
             // `uniform sampler2D name;`, read with texelFetch(name, evalPixel(), 0)
};

struct EvaluatorInput {
  std::string sampler;  // the sampler uniform the shader declares for it
  int components = 4;   // floats per texel: 1, 2 or 4 (OpenGL 3.3 has no 3-float buffer textures)
  InputLayout layout = InputLayout::Buffer;
  std::vector<float> values;  // texels in order, `components` floats each; PerPixel: row y = 0 first
};

class FragmentEvaluator {
 public:
  // The text put before the caller's source. It declares:
  //   uniform ivec2 evalOutputSize;              // W, H of the current evaluate()
  //   layout(location = 0) out vec4 evalResult;  // what each pixel stores
  //   ivec2 evalPixel();                         // this pixel's (x, y)
  //   int evalIndex();                           // y * W + x, this pixel's sample index
  static std::string_view prelude();

  // Builds the program from prelude() + `source`; `source` declares its
  // input samplers and main(), which writes evalResult. `gl` belongs to the
  // context current on this thread. Throws GlError with the build report
  // (line numbers count lines of fragmentSource()) if the shader does not
  // build. Destroy the evaluator with a context sharing its program current.
  FragmentEvaluator(const GlFunctions& gl, std::string_view source);

  // Draws one full-screen triangle into a fresh W×H RGBA32F framebuffer with
  // `inputs` bound, through `gl` (the current context's table), and returns
  // the W×H×4 floats read back: pixel (x, y) at [(y * width + x) * 4], rows
  // from y = 0. Floats pass through unchanged except for what the GL does to
  // them (llvmpipe flushes denormals to zero).
  //
  // Any context sharing objects with the one that built the evaluator may be
  // current: the program is shared, and the framebuffer and vertex array are
  // made per call because GL does not share them. Uniforms set on program()
  // beforehand persist. State left behind: framebuffer, program, vertex
  // array and texture bindings 0, active texture unit GL_TEXTURE0, blending,
  // scissor, culling, depth and stencil tests disabled, colour mask all on,
  // viewport W×H, GL_UNPACK_ALIGNMENT 4.
  //
  // Throws GlError for a bad size, an input that is malformed or that the
  // shader does not use as a sampler of the matching kind (a misspelt name
  // must not pass silently), an incomplete framebuffer, or any GL error.
  std::vector<float> evaluate(const GlFunctions& gl, int width, int height,
                              std::span<const EvaluatorInput> inputs = {}) const;

  // The complete fragment shader, prelude included, as compiled.
  const std::string& fragmentSource() const { return fragmentSource_; }
  GLuint program() const { return program_.get(); }

 private:
  std::string fragmentSource_;
  GlObject program_;
};

}  // namespace sdfwb::glcontext
