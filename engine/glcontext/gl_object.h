#pragma once
// Ownership of GL object names.

#include "glcontext/gl_functions.h"

namespace sdfwb::glcontext {

// Owns one GL object name and deletes it when destroyed. It keeps the delete
// entry point itself, not the table it came from, so it may outlive the
// context object that made it (a program built by a worker's shared context
// and used by the main one). Destroy it while a context that shares the
// object (for framebuffers and vertex arrays: the very context that made it)
// is current on the destroying thread. Move-only.
class GlObject {
 public:
  // Calls `deleteEntry` (a glDelete* entry point) for `name`.
  using Deleter = void (*)(GlProc deleteEntry, GLuint name);

  GlObject() = default;
  GlObject(GLuint name, GlProc deleteEntry, Deleter deleter)
      : name_(name), deleteEntry_(deleteEntry), deleter_(deleter) {}
  GlObject(GlObject&& other) noexcept;
  GlObject& operator=(GlObject&& other) noexcept;
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  ~GlObject() { reset(); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  // Gives up ownership without deleting; returns the name.
  GLuint release();
  // Deletes the object now (if any) and becomes empty.
  void reset();

 private:
  GLuint name_ = 0;
  GlProc deleteEntry_ = nullptr;
  Deleter deleter_ = nullptr;
};

// New, unbound objects of each kind (glGen*); empty if GL returned name 0.
GlObject makeBuffer(const GlFunctions& gl);
GlObject makeTexture(const GlFunctions& gl);
GlObject makeFramebuffer(const GlFunctions& gl);
GlObject makeRenderbuffer(const GlFunctions& gl);
GlObject makeVertexArray(const GlFunctions& gl);
GlObject makeQuery(const GlFunctions& gl);

// Takes ownership of a shader or program name (from glCreateShader or
// glCreateProgram, which return names rather than filling arrays).
GlObject adoptShader(const GlFunctions& gl, GLuint name);
GlObject adoptProgram(const GlFunctions& gl, GLuint name);

}  // namespace sdfwb::glcontext
