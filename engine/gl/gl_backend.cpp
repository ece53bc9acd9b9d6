#include "gl/gl_backend.h"

#include "gl/progressive_render.h"
#include "glcontext/osmesa_context.h"

namespace sdfwb::gl {
namespace {
constexpr int kProgressiveTileSize = 64;  // pixels per side of one draw, when the caller does not say
}  // namespace

GlBackend::GlBackend(glcontext::GlContext& context, std::unique_ptr<glcontext::GlContext> builderContext)
    : context_(context), renderer_(context.gl()) {
    if (builderContext) {
        // a caller that must not wait: programs build on a worker, grids in the background
        builder_ = std::make_unique<ProgramBuilder>(std::move(builderContext));
        renderer_.setWaitForGrid(false);
    }
}

GlBackend::GlBackend(std::unique_ptr<glcontext::GlContext> owned)
    : owned_(std::move(owned)), context_(*owned_), renderer_(context_.gl()) {}

GlBackend::~GlBackend() = default;

std::unique_ptr<GlBackend> GlBackend::headless() {
    return std::unique_ptr<GlBackend>(new GlBackend(glcontext::OsMesaContext::create()));
}

void GlBackend::prepare(const program::Program& program) {
    const int compiles = renderer_.counters().compiles;
    renderer_.warmUp(program);
    if (renderer_.counters().compiles != compiles) {
        lastPrepareSeconds_ = renderer_.counters().lastCompileSeconds;
        ++builds_;
    }
}

void GlBackend::adoptFinishedBuilds() {
    while (std::optional<BuiltProgram> built = builder_->take()) {
        if (built->linked) {
            renderer_.adoptProgram(built->program, std::move(built->linked));
            lastPrepareSeconds_ = built->seconds;
            ++builds_;
        } else {
            failedStructure_ = built->program.structureKey();
            failure_ = built->error;
        }
    }
}

render::Readiness GlBackend::readiness(const program::Program& program) {
    if (!builder_) return {};  // the first render builds on this thread
    adoptFinishedBuilds();
    if (failedStructure_ == program.structureKey()) return {false, failure_};
    if (renderer_.hasProgram(program)) return {};
    builder_->request(program);
    return {false, ""};
}

render::RenderOutcome GlBackend::render(const program::Program& program, const render::RenderControl& control) {
    return renderer_.render(program, control);
}

std::unique_ptr<render::ProgressiveRender> GlBackend::startProgressive(program::Program program,
                                                                       const render::RenderControl& control) {
    return std::make_unique<GlProgressiveRender>(renderer_, std::move(program), control, kProgressiveTileSize);
}

}  // namespace sdfwb::gl
