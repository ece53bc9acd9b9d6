#pragma once
// GL error checks. glGetError is polled after individual calls in debug
// builds only (SDFWB_GL_CHECK), since a check per call would cost every
// release build a driver round trip; checkGlError() itself works in any
// build, for the few places that must always verify (end of a readback).

#include <source_location>
#include <string>
#include <string_view>
#include <type_traits>

#include "glcontext/gl_functions.h"

// SDFWB_GL_DEBUG_CHECKS is 1 in builds without NDEBUG; define it before
// including this header to force the checks on or off.
#ifndef SDFWB_GL_DEBUG_CHECKS
#ifdef NDEBUG
#define SDFWB_GL_DEBUG_CHECKS 0
#else
#define SDFWB_GL_DEBUG_CHECKS 1
#endif
#endif

namespace sdfwb::glcontext {

// The symbolic name of a glGetError code ("GL_INVALID_ENUM"), or its hex
// value ("0x1234") for codes it does not know.
std::string glErrorName(GLenum error);

// Drains glGetError and returns the pending errors' names, comma-separated
// ("GL_INVALID_ENUM, GL_INVALID_VALUE"), or "" if there were none. A driver
// may queue one error per kind; a lost context may report errors forever,
// so at most 16 are read.
std::string takeGlErrors(const GlFunctions& gl);

// Drains glGetError and throws GlError if any error was pending, naming
// `call` and `where`: "GL_INVALID_ENUM after gl.Enable(cap) at gl_test.cpp:42".
// A driver may queue several errors; all are listed.
void checkGlError(const GlFunctions& gl, std::string_view call,
                  std::source_location where = std::source_location::current());

namespace detail {
template <class Call>
decltype(auto) checkedGlCall(const GlFunctions& gl, std::string_view text,
                             std::source_location where, Call&& call) {
  if constexpr (std::is_void_v<std::invoke_result_t<Call>>) {
    call();
    checkGlError(gl, text, where);
  } else {
    auto result = call();
    checkGlError(gl, text, where);
    return result;
  }
}
}  // namespace detail

}  // namespace sdfwb::glcontext

// SDFWB_GL_CHECK(gl, gl.BindTexture(GL_TEXTURE_2D, name)) performs the call
// and, when SDFWB_GL_DEBUG_CHECKS is 1, throws GlError if it raised a GL
// error, quoting the call's text and location. Usable as an expression:
// GLuint shader = SDFWB_GL_CHECK(gl, gl.CreateShader(GL_FRAGMENT_SHADER));
// Errors left pending by earlier unchecked calls are reported here too.
#if SDFWB_GL_DEBUG_CHECKS
#define SDFWB_GL_CHECK(gl, call)                                           \
  ::sdfwb::glcontext::detail::checkedGlCall((gl), #call,                   \
                                            std::source_location::current(), \
                                            [&]() -> decltype(auto) { return call; })
#else
#define SDFWB_GL_CHECK(gl, call) (call)
#endif
