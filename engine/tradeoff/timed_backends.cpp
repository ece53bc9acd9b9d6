#include "tradeoff/timed_backends.h"

#include <chrono>

#include "cpu/cpu_backend.h"
#include "gl/gl_backend.h"

namespace sdfwb::tradeoff {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Any backend of the contract, timed; its prepare() builds (and warms up) shaders.
class Timed final : public TimedBackend {
public:
    explicit Timed(std::unique_ptr<render::Backend> backend) : backend_(std::move(backend)) {}
    std::string name() const override { return backend_->name(); }
    void prepare(const program::Program& program) override { backend_->prepare(program); }
    std::optional<TimedFrame> render(const program::Program& program, const std::atomic<bool>* cancel) override {
        render::RenderControl control;
        control.cancel = cancel;
        auto start = std::chrono::steady_clock::now();
        render::RenderOutcome outcome = backend_->render(program, control);
        if (outcome.cancelled) return std::nullopt;
        return TimedFrame{std::move(outcome.frame), secondsSince(start)};
    }

private:
    std::unique_ptr<render::Backend> backend_;
};

}  // namespace

std::unique_ptr<TimedBackend> makeCpuBackend() { return std::make_unique<Timed>(std::make_unique<cpu::CpuBackend>()); }
std::unique_ptr<TimedBackend> makeGlBackend() { return std::make_unique<Timed>(gl::GlBackend::headless()); }

}  // namespace sdfwb::tradeoff
