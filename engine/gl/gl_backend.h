#pragma once
// The GLSL backend behind the backend contract (render/render_backend.h).
// It renders with a GL context that is current on the calling thread for
// every call; what differs from the CPU reference is the shader build, done
// in prepare() or, for a caller that must not wait, in the background.

#include <memory>
#include <optional>

#include "gl/gl_renderer.h"
#include "gl/program_builder.h"
#include "glcontext/gl_context.h"
#include "render/render_backend.h"

namespace sdfwb::gl {

class GlBackend : public render::Backend {
public:
    // Renders in `context` (not owned). With `builderContext` (sharing
    // objects with `context`), readiness() builds programs on a worker.
    explicit GlBackend(glcontext::GlContext& context, std::unique_ptr<glcontext::GlContext> builderContext = nullptr);
    // Renders in a headless OSMesa context of its own, current on the calling
    // thread from here on. Throws when OSMesa cannot make one.
    static std::unique_ptr<GlBackend> headless();
    ~GlBackend() override;

    std::string name() const override { return "gl"; }
    std::string device() const override { return context_.info().renderer; }
    // Builds the shader and warms it up (GlRenderer::warmUp).
    void prepare(const program::Program& program) override;
    double lastPrepareSeconds() const override { return lastPrepareSeconds_; }
    render::Readiness readiness(const program::Program& program) override;
    bool buildsIdle() const override { return !builder_ || !builder_->busy(); }
    render::RenderOutcome render(const program::Program& program, const render::RenderControl& control) override;
    std::unique_ptr<render::ProgressiveRender> startProgressive(program::Program program,
                                                                const render::RenderControl& control) override;

    int builds() const override { return builds_; }
    GlRenderer& renderer() { return renderer_; }

private:
    GlBackend(std::unique_ptr<glcontext::GlContext> owned);
    void adoptFinishedBuilds();

    std::unique_ptr<glcontext::GlContext> owned_;
    glcontext::GlContext& context_;
    GlRenderer renderer_;
    std::unique_ptr<ProgramBuilder> builder_;
    std::optional<std::uint64_t> failedStructure_;
    std::string failure_;
    double lastPrepareSeconds_ = 0;
    int builds_ = 0;
};

}  // namespace sdfwb::gl
