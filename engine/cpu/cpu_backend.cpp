#include "cpu/cpu_backend.h"

#include <chrono>
#include <mutex>
#include <utility>

#include "cpu/cpu_renderer.h"

namespace sdfwb::cpu {
namespace {

// The state a progressive render shares with its job, which may outlive the
// render object by the time it takes to notice a cancel.
struct Shared {
    program::Program program;
    image::Frame frame;  // each tile is written by one worker, then read by the caller
    std::mutex mutex;
    std::vector<render::TileRect> finished;  // since the last advance()
    double seconds = 0;
};

class CpuProgressiveRender : public render::ProgressiveRender {
public:
    CpuProgressiveRender(jobs::JobQueue& queue, program::Program program, render::RenderControl control)
        : shared_(std::make_shared<Shared>()) {
        shared_->frame = render::blankFrame(program.width, program.height);
        shared_->program = std::move(program);
        job_ = queue.submit([shared = shared_, control](jobs::Job& job) mutable {
            auto start = std::chrono::steady_clock::now();
            control.cancel = &job.cancelFlag();
            control.progress = [&](int done, int total) { job.setProgress(static_cast<double>(done) / total); };
            renderCpuTiles(shared->program, control, shared->frame, [&](const render::TileRect& tile) {
                std::lock_guard lock(shared->mutex);
                shared->finished.push_back(tile);
            });
            std::lock_guard lock(shared->mutex);
            shared->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        });
    }
    ~CpuProgressiveRender() override { job_->cancel(); }

    std::vector<render::TileRect> advance(double) override {
        bool finished = job_->finished();
        std::lock_guard lock(shared_->mutex);
        done_ = finished && !job_->cancelled();
        return std::exchange(shared_->finished, {});
    }
    bool done() const override { return done_; }
    double progress() const override { return done_ ? 1.0 : job_->progress(); }
    const image::Frame& frame() const override { return shared_->frame; }
    const program::Program& program() const override { return shared_->program; }
    double seconds() const override {
        std::lock_guard lock(shared_->mutex);
        return shared_->seconds;
    }

private:
    std::shared_ptr<Shared> shared_;
    jobs::JobHandle job_;
    bool done_ = false;  // as of the last advance(), which delivered every tile
};

}  // namespace

render::RenderOutcome CpuBackend::render(const program::Program& program, const render::RenderControl& control) {
    return renderCpu(program, control);
}

std::unique_ptr<render::ProgressiveRender> CpuBackend::startProgressive(program::Program program,
                                                                        const render::RenderControl& control) {
    render::RenderControl own = control;
    own.cancel = nullptr;
    own.progress = {};
    return std::make_unique<CpuProgressiveRender>(jobs_, std::move(program), own);
}

}  // namespace sdfwb::cpu
