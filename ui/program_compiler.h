#pragma once
// Scene -> program compiles (the instruction list and the prune grid, which
// can take seconds on a large scene) off the UI thread, for the viewport's
// lanes: the CPU-side half of making an image. A request returns at once; the
// caller polls take() each frame and draws what it has meanwhile. A newer
// request supersedes the last: its compile, still queued, is dropped, and one
// already running finishes unseen (compiles do not stop midway), so however
// fast requests come, at most one compile runs and one waits per compiler.
// The GL half (shader compile and link) is the GL backend's, on its worker
// with a context shared with the window's (render::Backend::readiness).
//
// The pattern of ui/pixel_probe.h on the engine's job queue: the worker
// writes into a result owned by that one request, so a superseded compile
// cannot overwrite a newer one.

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "jobs/job_queue.h"
#include "program/compile_scene.h"
#include "scene/scene.h"

namespace sdfwb::ui {

class ProgramCompiler {
public:
    // Compiles on `queue`'s workers; the queue may be shared (the
    // viewport's lanes share one) and must outlive the compiles it runs.
    explicit ProgramCompiler(jobs::JobQueue& queue) : queue_(queue) {}
    // A queued compile is dropped; a running one finishes into its own result.
    ~ProgramCompiler() { cancel(); }
    ProgramCompiler(const ProgramCompiler&) = delete;
    ProgramCompiler& operator=(const ProgramCompiler&) = delete;

    // Asks for `scene` compiled with `options`; `key` is the caller's name
    // for the pair (a scene state and the options), and the same key again
    // does nothing.
    void request(std::shared_ptr<const scene::Scene> scene, const program::CompileOptions& options, std::uint64_t key);
    // The last request's program once compiled, moved out (nullopt before,
    // and after it was taken or failed); never waits.
    std::optional<program::Program> take();
    // Why the last request's compile failed, or "".
    std::string error() const;
    // The last request is not compiled yet.
    bool pending() const { return job_ && !job_->finished(); }
    // Forgets the last request (dropped if still queued).
    void cancel();
    // Waits for the last request (tests; the UI polls).
    void wait() const {
        if (job_) job_->wait();
    }
    // Compiles that ran, superseded ones included.
    int compiles() const { return compiles_->load(); }

private:
    struct Result {
        std::optional<program::Program> program;  // written by the worker before it finishes
    };
    jobs::JobQueue& queue_;
    std::optional<std::uint64_t> key_;
    std::shared_ptr<Result> result_;
    jobs::JobHandle job_;
    std::shared_ptr<std::atomic<int>> compiles_ = std::make_shared<std::atomic<int>>(0);
};

}  // namespace sdfwb::ui
