#pragma once
// The one exception type of the glcontext module.

#include <stdexcept>

namespace sdfwb::glcontext {

// A GL or context failure: a missing library or entry point, a context that
// cannot be created or made current, a GL error caught by a check, a shader
// that does not build. what() names the cause; for shader builds it holds the
// formatted diagnostics (several lines, with the offending source lines).
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sdfwb::glcontext
