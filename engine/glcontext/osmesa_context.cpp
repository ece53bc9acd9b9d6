#include "glcontext/osmesa_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include "glcontext/gl_error.h"

namespace sdfwb::glcontext {

struct OsMesaLibrary {
  std::string name;
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaGetCurrentContext) getCurrentContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

namespace {

// The default framebuffer's size; see OsMesaContext::backingBuffer_.
constexpr int kBackingSize = 16;

template <class Function>
void bindSymbol(void* handle, const std::string& library, const char* symbol, Function& function) {
  dlerror();  // clear any earlier error so the one read below is ours
  function = reinterpret_cast<Function>(dlsym(handle, symbol));
  if (!function) {
    const char* why = dlerror();
    throw GlError("OSMesa library " + library + " has no symbol " + symbol + " (" +
                  (why ? why : "null symbol") + ")");
  }
}

std::shared_ptr<const OsMesaLibrary> loadLibrary(const std::vector<std::string>& names) {
  std::string failures;
  for (const std::string& name : names) {
    // RTLD_LOCAL keeps libOSMesa's gl* symbols out of the global scope, where
    // they would collide with libGL's (GLFW's window context). The library is
    // never dlclose'd: the entry points handed out point into it, and Mesa's
    // LLVM and dispatch state are not built to be unloaded mid-process.
    // dlopen of an already loaded library only bumps its reference count.
    void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      failures += (failures.empty() ? "" : "; ") + std::string(why ? why : name);
      continue;
    }
    auto library = std::make_shared<OsMesaLibrary>();
    library->name = name;
    bindSymbol(handle, name, "OSMesaCreateContextAttribs", library->createContextAttribs);
    bindSymbol(handle, name, "OSMesaDestroyContext", library->destroyContext);
    bindSymbol(handle, name, "OSMesaMakeCurrent", library->makeCurrent);
    bindSymbol(handle, name, "OSMesaGetCurrentContext", library->getCurrentContext);
    bindSymbol(handle, name, "OSMesaGetProcAddress", library->getProcAddress);
    return library;
  }
  if (names.empty()) failures = "no library names given";
  throw GlError("cannot load OSMesa for headless OpenGL (" + failures +
                "); install the libosmesa6 package");
}

osmesa_context* createContext(const OsMesaLibrary& library, const OsMesaOptions& options,
                              osmesa_context* shareWith) {
  // No depth, stencil or accumulation buffer: the default framebuffer is a
  // placeholder, rendering goes to framebuffer objects.
  const int attributes[] = {
      OSMESA_FORMAT, OSMESA_RGBA,
      OSMESA_DEPTH_BITS, 0,
      OSMESA_STENCIL_BITS, 0,
      OSMESA_ACCUM_BITS, 0,
      OSMESA_PROFILE, OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, options.major,
      OSMESA_CONTEXT_MINOR_VERSION, options.minor,
      0};
  osmesa_context* context = library.createContextAttribs(attributes, shareWith);
  if (!context) {
    throw GlError("OSMesaCreateContextAttribs (" + library.name + ") could not create an OpenGL " +
                  std::to_string(options.major) + "." + std::to_string(options.minor) +
                  " core profile context" + (shareWith ? " sharing objects with another" : ""));
  }
  return context;
}

}  // namespace

OsMesaContext::OsMesaContext(std::shared_ptr<const OsMesaLibrary> library, osmesa_context* context,
                             const OsMesaOptions& options)
    : library_(std::move(library)),
      context_(context),
      options_(options),
      backingBuffer_(std::size_t{kBackingSize} * kBackingSize * 4) {
  try {
    // OSMesaGetProcAddress answers from Mesa's dispatch layer without a
    // current context, so a context's table can be filled before it is ever
    // made current (createShared relies on this).
    gl_ = GlFunctions::load([this](const char* name) { return getProcAddress(name); });
  } catch (...) {
    library_->destroyContext(context_);
    throw;
  }
}

std::unique_ptr<OsMesaContext> OsMesaContext::create(const OsMesaOptions& options) {
  std::shared_ptr<const OsMesaLibrary> library = loadLibrary(options.libraryNames);
  std::unique_ptr<OsMesaContext> context(
      new OsMesaContext(library, createContext(*library, options, nullptr), options));
  context->makeCurrent();
  context->info_ = queryContextInfo(context->gl_);
  // OSMesaGetProcAddress hands out stubs for anything named gl*, so the
  // version is the only real evidence that the entry points exist.
  requireVersion(context->info_, options.major, options.minor);
  return context;
}

OsMesaContext::~OsMesaContext() {
  releaseCurrent();
  library_->destroyContext(context_);
}

void OsMesaContext::makeCurrent() {
  if (!library_->makeCurrent(context_, backingBuffer_.data(), GL_UNSIGNED_BYTE, kBackingSize,
                             kBackingSize)) {
    throw GlError("OSMesaMakeCurrent (" + library_->name + ") failed to make the context current");
  }
}

void OsMesaContext::releaseCurrent() {
  if (library_->getCurrentContext() == context_) {
    library_->makeCurrent(nullptr, nullptr, 0, 0, 0);
  }
}

std::unique_ptr<GlContext> OsMesaContext::createShared() {
  std::unique_ptr<OsMesaContext> shared(
      new OsMesaContext(library_, createContext(*library_, options_, context_), options_));
  // Same library and attributes, so the same renderer and version; reading
  // them would need the new context current, which this call must not do.
  shared->info_ = info_;
  return shared;
}

GlProc OsMesaContext::getProcAddress(const char* name) const {
  return library_->getProcAddress(name);
}

const std::string& OsMesaContext::libraryName() const { return library_->name; }

}  // namespace sdfwb::glcontext
