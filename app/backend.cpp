#include "app/backend.h"

#include <chrono>

#include "gl/gl_renderer.h"
#include "gl/shader_generator.h"
#include "glcontext/osmesa_context.h"
#include "io/atomic_file.h"

namespace sdfwb::app {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BackendResult renderGl(const program::Program& program, const BackendRequest& request) {
    auto start = std::chrono::steady_clock::now();
    if (!request.dumpShader.empty()) {
        io::writeTextAtomically(request.dumpShader, gl::generateFragmentShader(program));
    }
    auto context = glcontext::OsMesaContext::create();
    gl::GlRenderer renderer(context->gl());
    renderer.prepare(program);
    gl::GlRenderControl control;
    control.cancel = request.cancel;
    control.progress = request.progress;
    gl::GlRenderOutcome outcome = renderer.render(program, control);
    BackendResult result;
    result.frame = std::move(outcome.frame);
    result.cancelled = outcome.cancelled;
    result.compileSeconds = renderer.counters().lastCompileSeconds;
    result.glRenderer = context->info().renderer;
    result.seconds = secondsSince(start);
    return result;
}

}  // namespace

BackendResult renderWithBackend(const program::Program& program, const BackendRequest& request) {
    if (request.backend == Backend::Gl) {
        return renderGl(program, request);
    }
    auto start = std::chrono::steady_clock::now();
    cpu::RenderControl control;
    control.threads = request.threads;
    control.precision = request.precision;
    control.cancel = request.cancel;
    control.progress = request.progress;
    cpu::RenderOutcome outcome = cpu::renderCpu(program, control);
    BackendResult result;
    result.frame = std::move(outcome.frame);
    result.cancelled = outcome.cancelled;
    result.seconds = secondsSince(start);
    return result;
}

}  // namespace sdfwb::app
