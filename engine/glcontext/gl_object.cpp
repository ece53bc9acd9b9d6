#include "glcontext/gl_object.h"

#include <type_traits>
#include <utility>

namespace sdfwb::glcontext {

GlObject::GlObject(GlObject&& other) noexcept
    : name_(std::exchange(other.name_, 0)), deleteEntry_(other.deleteEntry_), deleter_(other.deleter_) {}

GlObject& GlObject::operator=(GlObject&& other) noexcept {
  if (this != &other) {
    reset();
    name_ = std::exchange(other.name_, 0);
    deleteEntry_ = other.deleteEntry_;
    deleter_ = other.deleter_;
  }
  return *this;
}

GLuint GlObject::release() { return std::exchange(name_, 0); }

void GlObject::reset() {
  if (name_ != 0) deleter_(deleteEntry_, std::exchange(name_, 0));
}

namespace {

// Type of the table member `Member`, e.g. PFNGLDELETETEXTURESPROC.
template <auto GlFunctions::*Member>
using EntryType = std::remove_cvref_t<decltype(std::declval<GlFunctions>().*Member)>;

// glGen*/glDelete* take arrays; these adapt them to one name. The entry
// point is stored type-erased and cast back to its own type to be called.
template <auto GlFunctions::*Generate, auto GlFunctions::*Delete>
GlObject makeObject(const GlFunctions& gl) {
  GLuint name = 0;
  (gl.*Generate)(1, &name);
  return GlObject(name, reinterpret_cast<GlProc>(gl.*Delete), [](GlProc entry, GLuint doomed) {
    reinterpret_cast<EntryType<Delete>>(entry)(1, &doomed);
  });
}

template <auto GlFunctions::*Delete>
GlObject adoptObject(const GlFunctions& gl, GLuint name) {
  return GlObject(name, reinterpret_cast<GlProc>(gl.*Delete), [](GlProc entry, GLuint doomed) {
    reinterpret_cast<EntryType<Delete>>(entry)(doomed);
  });
}

}  // namespace

GlObject makeBuffer(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenBuffers, &GlFunctions::DeleteBuffers>(gl);
}
GlObject makeTexture(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenTextures, &GlFunctions::DeleteTextures>(gl);
}
GlObject makeFramebuffer(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenFramebuffers, &GlFunctions::DeleteFramebuffers>(gl);
}
GlObject makeRenderbuffer(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenRenderbuffers, &GlFunctions::DeleteRenderbuffers>(gl);
}
GlObject makeVertexArray(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenVertexArrays, &GlFunctions::DeleteVertexArrays>(gl);
}
GlObject makeQuery(const GlFunctions& gl) {
  return makeObject<&GlFunctions::GenQueries, &GlFunctions::DeleteQueries>(gl);
}

GlObject adoptShader(const GlFunctions& gl, GLuint name) {
  return adoptObject<&GlFunctions::DeleteShader>(gl, name);
}
GlObject adoptProgram(const GlFunctions& gl, GLuint name) {
  return adoptObject<&GlFunctions::DeleteProgram>(gl, name);
}

}  // namespace sdfwb::glcontext
