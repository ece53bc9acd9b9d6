#include "gl/program_builder.h"

#include <chrono>

namespace sdfwb::gl {

ProgramBuilder::ProgramBuilder(std::unique_ptr<glcontext::GlContext> context)
    : context_(std::move(context)), worker_([this] { run(); }) {}

ProgramBuilder::~ProgramBuilder() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    worker_.join();
    done_.clear();  // programs nobody adopted are deleted here, with the caller's context current
}

void ProgramBuilder::request(const program::Program& program) {
    std::uint64_t key = program.structureKey();
    {
        std::lock_guard lock(mutex_);
        if ((queued_ && queued_->structureKey() == key) || running_ == key) return;
        for (const BuiltProgram& built : done_) {
            if (built.program.structureKey() == key) return;
        }
        queued_ = program;
    }
    wake_.notify_all();
}

std::optional<BuiltProgram> ProgramBuilder::take() {
    std::lock_guard lock(mutex_);
    if (done_.empty()) return std::nullopt;
    BuiltProgram built = std::move(done_.front());
    done_.pop_front();
    return built;
}

bool ProgramBuilder::busy() const {
    std::lock_guard lock(mutex_);
    return queued_.has_value() || running_.has_value();
}

void ProgramBuilder::run() {
    glcontext::ScopedCurrent current(*context_);
    GlRenderer renderer(context_->gl());
    for (;;) {
        program::Program program;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || queued_.has_value(); });
            if (stop_) return;
            program = std::move(*queued_);
            queued_.reset();
            running_ = program.structureKey();
        }
        auto start = std::chrono::steady_clock::now();
        BuiltProgram built;
        try {
            // The warm-up draws a few pixels with the very state the real
            // renders use, so the driver's per-state code is generated here.
            program::Program warmUp = program;
            warmUp.width = warmUp.height = 4;
            warmUp.aa = 1;
            renderer.render(warmUp);
            built.linked = renderer.releaseProgram(program);
            context_->gl().Finish();
        } catch (const std::exception& error) {
            built.error = error.what();
        }
        built.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        built.program = std::move(program);
        std::lock_guard lock(mutex_);
        running_.reset();
        done_.push_back(std::move(built));
    }
}

}  // namespace sdfwb::gl
