#pragma once
// Choosing a backend (the one place that names both) and rendering a
// compiled scene with it, for the command-line tools and the snapshot export.

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "glcontext/gl_context.h"
#include "image/image.h"
#include "program/program.h"
#include "render/render_backend.h"

namespace sdfwb::app {

enum class Backend { Cpu, Gl };

// The CPU reference, or the GL backend rendering in `context` (current on
// the calling thread for the backend's life) or, without one, in a headless
// OSMesa context of its own. Throws (glcontext::GlError) with one line naming
// the cause when no GL context can be made.
std::unique_ptr<render::Backend> makeBackend(Backend kind, glcontext::GlContext* context = nullptr);

struct BackendRequest {
    Backend backend = Backend::Cpu;
    int threads = 0;                                       // cpu
    render::Precision precision = render::Precision::Float;  // cpu
    std::string dumpShader;                                // gl: write the generated shader here
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(int done, int total)> progress;
};

struct BackendResult {
    image::Frame frame;
    bool cancelled = false;
    double seconds = 0;         // the whole render, shader build included
    double compileSeconds = 0;  // gl: generating and building the shader
    std::string device;         // the backend's device (GL_RENDERER for gl)
};

// Throws std::runtime_error (or glcontext::GlError) with one line naming the cause
// when the GL backend cannot run (no OSMesa, context failure, shader build report).
BackendResult renderWithBackend(const program::Program& program, const BackendRequest& request);

}  // namespace sdfwb::app
