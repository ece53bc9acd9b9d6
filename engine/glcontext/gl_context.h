#pragma once
// The GL context contract the engine renders with. A provider implements it:
// OsMesaContext here (headless), a hidden GLFW window in app/ for the GUI.
// The engine only ever uses the context that is current, through the entry
// points loaded for it, so it never needs to know which provider made it.

#include <memory>
#include <string>

#include "glcontext/gl_functions.h"

namespace sdfwb::glcontext {

// What a context reports about itself (glGetString and version integers).
struct GlContextInfo {
  std::string vendor;       // GL_VENDOR, e.g. "Mesa/X.org"
  std::string renderer;     // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;      // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  std::string glslVersion;  // GL_SHADING_LANGUAGE_VERSION, e.g. "4.50"
  int major = 0;            // GL_MAJOR_VERSION
  int minor = 0;            // GL_MINOR_VERSION
  bool coreProfile = false; // GL_CONTEXT_CORE_PROFILE_BIT set in GL_CONTEXT_PROFILE_MASK
};

// Reads GlContextInfo from the context current on this thread, which `gl`
// must belong to.
GlContextInfo queryContextInfo(const GlFunctions& gl);

// Throws GlError unless `info` describes an OpenGL `major`.`minor` or later
// core profile context, naming what was offered instead.
void requireVersion(const GlContextInfo& info, int major, int minor);

// An OpenGL 3.3 core (or later) context. Thread rules are OpenGL's: a
// context is current on at most one thread at a time, and GL calls go to the
// context current on the calling thread. Not copyable.
class GlContext {
 public:
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  // Destroying a context releases it from the calling thread if it is
  // current there; it must not be current on any other thread.
  virtual ~GlContext() = default;

  // Makes this context current on the calling thread, replacing a context of
  // the same provider. A context of another provider (GLFW versus OSMesa)
  // must be released first: Mesa's GLX and OSMesa share one per-thread
  // dispatch (docs/toolchain-notes.md). Throws GlError if the provider refuses.
  virtual void makeCurrent() = 0;

  // Leaves no context current on the calling thread if this one is current
  // there; otherwise does nothing.
  virtual void releaseCurrent() = 0;

  // Creates a context sharing this one's objects (buffers, textures,
  // programs, sync objects; not framebuffers or vertex arrays, which GL never
  // shares), for a worker thread to make current. Call it on the thread that
  // owns this context (GLFW needs the main thread). The new context is not
  // current anywhere, and what was current on the calling thread stays so.
  // Objects made in one context are visible in the other only after a fence
  // (FenceSync + Flush there, ClientWaitSync or WaitSync here).
  virtual std::unique_ptr<GlContext> createShared() = 0;

  // The entry points loaded for this context. Call them only while this
  // context is current on the calling thread.
  virtual const GlFunctions& gl() const = 0;

  // The context's vendor, renderer and version, read when it was created.
  virtual const GlContextInfo& info() const = 0;
};

// Makes a context current for a scope and releases it at the end: the
// pattern for a worker thread that owns a shared context.
class ScopedCurrent {
 public:
  explicit ScopedCurrent(GlContext& context) : context_(context) { context_.makeCurrent(); }
  ~ScopedCurrent() { context_.releaseCurrent(); }
  ScopedCurrent(const ScopedCurrent&) = delete;
  ScopedCurrent& operator=(const ScopedCurrent&) = delete;

 private:
  GlContext& context_;
};

}  // namespace sdfwb::glcontext
