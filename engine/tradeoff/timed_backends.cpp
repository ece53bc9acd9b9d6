#include "tradeoff/timed_backends.h"

#include <chrono>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "glcontext/osmesa_context.h"

namespace sdfwb::tradeoff {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class CpuBackend final : public TimedBackend {
public:
    std::string name() const override { return "cpu"; }
    void prepare(const program::Program&) override {}
    std::optional<TimedFrame> render(const program::Program& program, const std::atomic<bool>* cancel) override {
        cpu::RenderControl control;
        control.cancel = cancel;
        auto start = std::chrono::steady_clock::now();
        cpu::RenderOutcome outcome = cpu::renderCpu(program, control);
        if (outcome.cancelled) return std::nullopt;
        return TimedFrame{std::move(outcome.frame), secondsSince(start)};
    }
};

class GlBackend final : public TimedBackend {
public:
    GlBackend() : context_(glcontext::OsMesaContext::create()), renderer_(context_->gl()) {}
    std::string name() const override { return "gl"; }
    void prepare(const program::Program& program) override {
        renderer_.prepare(program);
        // llvmpipe compiles the shader to machine code at its first draw: a
        // tiny draw pays for that outside the timed renders
        program::Program tiny = program;
        tiny.width = tiny.height = 8;
        tiny.aa = 1;
        renderer_.render(tiny);
    }
    std::optional<TimedFrame> render(const program::Program& program, const std::atomic<bool>* cancel) override {
        gl::GlRenderControl control;
        control.cancel = cancel;
        auto start = std::chrono::steady_clock::now();
        gl::GlRenderOutcome outcome = renderer_.render(program, control);
        if (outcome.cancelled) return std::nullopt;
        return TimedFrame{std::move(outcome.frame), secondsSince(start)};
    }

private:
    std::unique_ptr<glcontext::OsMesaContext> context_;
    gl::GlRenderer renderer_;
};

}  // namespace

std::unique_ptr<TimedBackend> makeCpuBackend() { return std::make_unique<CpuBackend>(); }
std::unique_ptr<TimedBackend> makeGlBackend() { return std::make_unique<GlBackend>(); }

}  // namespace sdfwb::tradeoff
