#include "gl/program_builder.h"

#include <algorithm>
#include <chrono>

namespace sdfwb::gl {

ProgramBuilder::ProgramBuilder(std::unique_ptr<glcontext::GlContext> context)
    : context_(std::move(context)), queue_(1, [this](const std::function<void()>& runJobs) {
          glcontext::ScopedCurrent current(*context_);
          GlRenderer renderer(context_->gl());
          workerRenderer_ = &renderer;
          runJobs();
          workerRenderer_ = nullptr;
      }) {}

ProgramBuilder::~ProgramBuilder() = default;

void ProgramBuilder::request(const program::Program& program) {
    const std::uint64_t key = program.structureKey();
    for (const Pending& p : pending_) {
        if (p.structure == key && !p.job->cancelled()) return;
    }
    for (Pending& p : pending_) {
        if (!p.job->started()) p.job->cancel();
    }
    auto result = std::make_shared<BuiltProgram>();
    result->program = program;
    jobs::JobHandle job = queue_.submit([this, result](jobs::Job&) {
        auto start = std::chrono::steady_clock::now();
        try {
            workerRenderer_->warmUp(result->program);
            result->linked = workerRenderer_->releaseProgram(result->program);
            context_->gl().Finish();
        } catch (const std::exception& error) {
            result->error = error.what();
        }
        result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    pending_.push_back({key, std::move(job), std::move(result)});
}

std::optional<BuiltProgram> ProgramBuilder::take() {
    std::erase_if(pending_, [](const Pending& p) { return p.job->cancelled() && p.job->finished(); });
    auto built = std::find_if(pending_.begin(), pending_.end(), [](const Pending& p) { return p.job->finished(); });
    if (built == pending_.end()) return std::nullopt;
    BuiltProgram result = std::move(*built->result);
    pending_.erase(built);
    return result;
}

bool ProgramBuilder::busy() const {
    return std::any_of(pending_.begin(), pending_.end(), [](const Pending& p) { return !p.job->finished(); });
}

void ProgramBuilder::wait() const {
    for (const Pending& p : pending_) p.job->wait();
}

}  // namespace sdfwb::gl
