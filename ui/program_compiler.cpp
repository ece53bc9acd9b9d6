#include "ui/program_compiler.h"

#include <utility>

namespace sdfwb::ui {

void ProgramCompiler::request(std::shared_ptr<const scene::Scene> scene, const program::CompileOptions& options,
                              std::uint64_t key) {
    if (key_ == key) return;
    cancel();
    key_ = key;
    result_ = std::make_shared<Result>();
    job_ = queue_.submit([scene = std::move(scene), options, result = result_, compiles = compiles_](jobs::Job&) {
        ++*compiles;
        result->program = program::compileScene(*scene, options);
    });
}

std::optional<program::Program> ProgramCompiler::take() {
    if (!job_ || !job_->finished() || !result_) return std::nullopt;
    return std::exchange(result_->program, std::nullopt);
}

std::string ProgramCompiler::error() const { return job_ && job_->finished() ? job_->error() : std::string(); }

void ProgramCompiler::cancel() {
    // a compile that started cannot stop: it runs to the end into its own
    // result, which nobody reads
    if (job_ && !job_->started()) job_->cancel();
    job_.reset();
    result_.reset();
    key_.reset();
}

}  // namespace sdfwb::ui
