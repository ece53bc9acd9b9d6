#include "glcontext/gl_debug.h"

#include <cstdio>

namespace sdfwb::glcontext {

std::string glErrorName(GLenum error) {
  switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: break;
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", error);
  return hex;
}

std::string takeGlErrors(const GlFunctions& gl) {
  std::string errors;
  for (int i = 0; i < 16; ++i) {
    GLenum error = gl.GetError();
    if (error == GL_NO_ERROR) break;
    if (!errors.empty()) errors += ", ";
    errors += glErrorName(error);
  }
  return errors;
}

void checkGlError(const GlFunctions& gl, std::string_view call, std::source_location where) {
  std::string errors = takeGlErrors(gl);
  if (errors.empty()) return;
  std::string file = where.file_name();
  if (auto slash = file.find_last_of('/'); slash != std::string::npos) file.erase(0, slash + 1);
  throw GlError(errors + " after " + std::string(call) + " at " + file + ":" +
                std::to_string(where.line()));
}

}  // namespace sdfwb::glcontext
