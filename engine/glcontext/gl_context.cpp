#include "glcontext/gl_context.h"

#include "glcontext/gl_debug.h"
#include "glcontext/gl_error.h"

namespace sdfwb::glcontext {

namespace {
std::string glString(const GlFunctions& gl, GLenum name) {
  // Null when no context is current: the strings then read as empty.
  const GLubyte* text = gl.GetString(name);
  return text ? reinterpret_cast<const char*>(text) : std::string();
}

GLint glInteger(const GlFunctions& gl, GLenum name) {
  GLint value = 0;
  gl.GetIntegerv(name, &value);
  return value;
}
}  // namespace

GlContextInfo queryContextInfo(const GlFunctions& gl) {
  GlContextInfo info;
  info.vendor = glString(gl, GL_VENDOR);
  info.renderer = glString(gl, GL_RENDERER);
  info.version = glString(gl, GL_VERSION);
  info.glslVersion = glString(gl, GL_SHADING_LANGUAGE_VERSION);
  // GL_MAJOR_VERSION and the profile mask exist from 3.0 and 3.2; an older
  // context leaves them 0 and fails requireVersion().
  info.major = glInteger(gl, GL_MAJOR_VERSION);
  info.minor = glInteger(gl, GL_MINOR_VERSION);
  info.coreProfile = (glInteger(gl, GL_CONTEXT_PROFILE_MASK) & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
  // The queries above may have raised errors on an old context; do not leave
  // them for the caller's next check to misattribute.
  takeGlErrors(gl);
  return info;
}

void requireVersion(const GlContextInfo& info, int major, int minor) {
  bool recentEnough = info.major > major || (info.major == major && info.minor >= minor);
  if (recentEnough && info.coreProfile) return;
  std::string wanted = std::to_string(major) + "." + std::to_string(minor);
  std::string offered = info.version.empty() ? "no version string" : "\"" + info.version + "\"";
  throw GlError("need an OpenGL " + wanted + " core profile context, got " + offered +
                " from renderer \"" + info.renderer + "\"");
}

}  // namespace sdfwb::glcontext
