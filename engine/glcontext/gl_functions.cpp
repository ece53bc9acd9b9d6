#include "glcontext/gl_functions.h"

namespace sdfwb::glcontext {

GlFunctions GlFunctions::load(const ProcLoader& loader) {
  GlFunctions gl;
  // One block per entry point, in list order, so the first missing one is
  // the one reported.
#define SDFWB_GL_LOAD_MEMBER(type, name)                                                        \
  if (GlProc proc = loader("gl" #name)) {                                                       \
    gl.name = reinterpret_cast<type>(proc);                                                     \
  } else {                                                                                      \
    throw GlError("OpenGL entry point gl" #name " is missing (the context's loader returned null)"); \
  }
  SDFWB_GL_FUNCTIONS(SDFWB_GL_LOAD_MEMBER)
#undef SDFWB_GL_LOAD_MEMBER
  return gl;
}

}  // namespace sdfwb::glcontext
