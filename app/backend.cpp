#include "app/backend.h"

#include <chrono>
#include <stdexcept>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"
#include "gl/program_size.h"
#include "gl/shader_generator.h"
#include "io/atomic_file.h"

namespace sdfwb::app {

std::unique_ptr<render::Backend> makeBackend(Backend kind, glcontext::GlContext* context) {
    switch (kind) {
    case Backend::Cpu: return std::make_unique<cpu::CpuBackend>();
    case Backend::Gl: return context ? std::make_unique<gl::GlBackend>(*context) : gl::GlBackend::headless();
    }
    throw std::logic_error("makeBackend: unknown backend");
}

BackendResult renderWithBackend(const program::Program& program, const BackendRequest& request) {
    if (request.backend == Backend::Gl) {
        if (std::string problem = gl::shaderSizeProblem(program); !problem.empty()) {
            throw std::invalid_argument(problem);
        }
    }
    auto start = std::chrono::steady_clock::now();
    if (request.backend == Backend::Gl && !request.dumpShader.empty()) {
        io::writeTextAtomically(request.dumpShader, gl::generateFragmentShader(program));
    }
    std::unique_ptr<render::Backend> backend = makeBackend(request.backend);
    backend->prepare(program);
    render::RenderControl control;
    control.threads = request.threads;
    control.precision = request.precision;
    control.cancel = request.cancel;
    control.progress = request.progress;
    render::RenderOutcome outcome = backend->render(program, control);
    BackendResult result;
    result.frame = std::move(outcome.frame);
    result.cancelled = outcome.cancelled;
    result.compileSeconds = backend->lastPrepareSeconds();
    result.device = backend->device();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace sdfwb::app
