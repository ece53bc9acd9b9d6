#pragma once
// Headless GL contexts from Mesa's OSMesa (llvmpipe on this project's
// machines), for rendering without a display or GPU.
//
// libOSMesa is loaded with dlopen, never linked: it exports the same gl*
// symbols as libGL, and the one executable also links GLFW for the GUI.
// OSMesa and GLFW contexts may live in one process on different threads;
// on one thread, release the GLFW context (glfwMakeContextCurrent(nullptr))
// before making an OSMesa context current, and call it again before making
// the window current afterwards (docs/toolchain-notes.md, "GL and OSMesa").

#include <memory>
#include <string>
#include <vector>

#include "glcontext/gl_context.h"

// OSMesa's context type (osmesa.h: typedef struct osmesa_context *OSMesaContext).
struct osmesa_context;

namespace sdfwb::glcontext {

struct OsMesaOptions {
  // Library names passed to dlopen, tried in order. The versioned name comes
  // first because the unversioned symlink ships only with libosmesa6-dev.
  std::vector<std::string> libraryNames = {"libOSMesa.so.8", "libOSMesa.so"};
  int major = 3;  // requested OpenGL core profile version; Mesa may give a
  int minor = 3;  // later one (llvmpipe gives 4.5)
};

// The OSMesa library as loaded; shared by every context made from it.
struct OsMesaLibrary;

class OsMesaContext final : public GlContext {
 public:
  // Loads the library, creates a core profile context of options.major.minor
  // or later, makes it current on the calling thread and loads its entry
  // points. Throws GlError with one line naming the cause: no library could
  // be loaded (with each dlerror text), a symbol is missing, context creation
  // failed, or the context is older than requested.
  static std::unique_ptr<OsMesaContext> create(const OsMesaOptions& options = {});

  ~OsMesaContext() override;

  void makeCurrent() override;
  void releaseCurrent() override;
  // The new context shares objects with this one and has its own backing
  // buffer, so it can be current on another thread at the same time.
  std::unique_ptr<GlContext> createShared() override;
  const GlFunctions& gl() const override { return gl_; }
  const GlContextInfo& info() const override { return info_; }

  // OSMesaGetProcAddress. Beware: it returns a non-null no-op stub for any
  // name starting with "gl", known or not (calling it raises
  // GL_INVALID_OPERATION), so a non-null result proves nothing.
  GlProc getProcAddress(const char* name) const;

  // The file the library was loaded from, as given to dlopen.
  const std::string& libraryName() const;

 private:
  OsMesaContext(std::shared_ptr<const OsMesaLibrary> library, osmesa_context* context,
                const OsMesaOptions& options);

  std::shared_ptr<const OsMesaLibrary> library_;
  osmesa_context* context_;
  OsMesaOptions options_;
  // OSMesaMakeCurrent needs a colour buffer even though rendering goes to
  // framebuffer objects; a tiny one is the default framebuffer.
  std::vector<unsigned char> backingBuffer_;
  GlFunctions gl_;
  GlContextInfo info_;
};

}  // namespace sdfwb::glcontext
