#pragma once
// Rendering a compiled scene with either backend, for the command-line tools.

#include <atomic>
#include <functional>
#include <string>

#include "cpu/cpu_renderer.h"
#include "image/image.h"
#include "program/program.h"

namespace sdfwb::app {

enum class Backend { Cpu, Gl };

struct BackendRequest {
    Backend backend = Backend::Cpu;
    int threads = 0;                                 // cpu
    cpu::Precision precision = cpu::Precision::Float;  // cpu
    std::string dumpShader;                          // gl: write the generated shader here
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(int done, int total)> progress;
};

struct BackendResult {
    image::Frame frame;
    bool cancelled = false;
    double seconds = 0;         // the whole render, shader build included
    double compileSeconds = 0;  // gl: generating and building the shader
    std::string glRenderer;     // gl: GL_RENDERER of the headless context
};

// Throws std::runtime_error (or glcontext::GlError) with one line naming the cause
// when the GL backend cannot run (no OSMesa, context failure, shader build report).
BackendResult renderWithBackend(const program::Program& program, const BackendRequest& request);

}  // namespace sdfwb::app
