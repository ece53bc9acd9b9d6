#pragma once
// Scene -> program compiles (the instruction list and the prune grid, which
// can take seconds on a large scene) off the UI thread, for the viewport's
// lanes: the CPU-side half of making an image. A request returns at once; the
// caller polls take() each frame and draws what it has meanwhile. A newer
// request supersedes the last: its compile, still queued, is dropped; one
// that already started (compiles do not stop midway) or finished untaken is
// kept as the freshest program on the way, which take() hands out (with its
// tag) until the newest request's own is ready. So however fast requests
// come, at most one compile runs and one waits per compiler, and during a
// drag, where every frame is a new request, each frame can still show the
// state of the frame before. The GL half (shader compile and link) is the GL
// backend's, on its worker with a context shared with the window's
// (render::Backend::readiness).
//
// The pattern of ui/pixel_probe.h on the engine's job queue: each request's
// worker writes into a result owned by that request alone, so a superseded
// compile cannot overwrite a newer one.

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "jobs/job_queue.h"
#include "program/compile_scene.h"
#include "scene/scene.h"

namespace sdfwb::ui {

// `Tag` names a request (a scene state and the options, as the caller counts
// them): equal tags are the same request. It comes back with the program.
template <typename Tag>
class ProgramCompiler {
public:
    using Compile = std::function<program::Program(const scene::Scene&, const program::CompileOptions&)>;
    struct Compiled {
        program::Program program;
        Tag tag;
    };

    // Compiles on `queue`'s workers; the queue may be shared (the viewport's
    // lanes share one) and must outlive the compiles it runs. `compile` is
    // program::compileScene but in tests.
    explicit ProgramCompiler(jobs::JobQueue& queue, Compile compile = program::compileScene)
        : queue_(queue), compile_(std::move(compile)) {}
    // A queued compile is dropped; a running one finishes into its own result.
    ~ProgramCompiler() { cancel(); }
    ProgramCompiler(const ProgramCompiler&) = delete;
    ProgramCompiler& operator=(const ProgramCompiler&) = delete;

    // Asks for `scene` compiled with `options`. The same tag again does
    // nothing while its program is on the way or not taken yet; once taken,
    // asking again means the caller dropped it (the viewport replans a lane
    // when a drag starts or ends on an unchanged scene), so it compiles again:
    // waiting for a program already handed out left the viewport "compiling
    // the scene" until the next edit.
    void request(std::shared_ptr<const scene::Scene> scene, const program::CompileOptions& options, const Tag& tag);
    // The newest finished program not taken yet, moved out: the last
    // request's, or before it is ready the one it superseded after that one
    // started (check the tag); nullopt when there is none. Never waits.
    std::optional<Compiled> take();
    // Why the last request's compile failed, or "".
    std::string error() const { return last_ && last_->job->finished() ? last_->job->error() : std::string(); }
    // The last request is not compiled yet.
    bool pending() const { return last_ && !last_->job->finished(); }
    // Forgets every request (the last one dropped if still queued).
    void cancel();
    // Waits for the last request (tests; the UI polls).
    void wait() const {
        if (last_) last_->job->wait();
    }
    // Compiles that ran, superseded ones included.
    int compiles() const { return compiles_->load(); }

private:
    struct Request {
        Tag tag;
        jobs::JobHandle job;
        std::shared_ptr<std::optional<program::Program>> program;  // written by the worker before it finishes
        bool taken = false;
    };
    static std::optional<Compiled> takeFrom(std::optional<Request>& request);

    jobs::JobQueue& queue_;
    Compile compile_;
    std::optional<Request> last_;        // the newest request
    std::optional<Request> superseded_;  // the one before, started when superseded: the freshest on the way
    std::shared_ptr<std::atomic<int>> compiles_ = std::make_shared<std::atomic<int>>(0);
};

template <typename Tag>
void ProgramCompiler<Tag>::request(std::shared_ptr<const scene::Scene> scene, const program::CompileOptions& options,
                                   const Tag& tag) {
    if (last_ && last_->tag == tag && !last_->taken) return;
    if (last_) {
        if (last_->job->started()) {
            superseded_ = std::move(last_);  // it will finish: newer than anything taken before
        } else {
            last_->job->cancel();  // never ran: dropped
        }
    }
    auto program = std::make_shared<std::optional<program::Program>>();
    jobs::JobHandle job = queue_.submit(
        [scene = std::move(scene), options, program, compile = compile_, compiles = compiles_](jobs::Job&) {
            ++*compiles;
            *program = compile(*scene, options);
        });
    last_ = Request{tag, std::move(job), std::move(program)};
}

template <typename Tag>
std::optional<typename ProgramCompiler<Tag>::Compiled> ProgramCompiler<Tag>::takeFrom(std::optional<Request>& request) {
    if (!request || !request->job->finished() || !*request->program) return std::nullopt;
    Compiled compiled{std::move(**request->program), request->tag};
    request->program->reset();
    request->taken = true;
    return compiled;
}

template <typename Tag>
std::optional<typename ProgramCompiler<Tag>::Compiled> ProgramCompiler<Tag>::take() {
    if (std::optional<Compiled> newest = takeFrom(last_)) {
        superseded_.reset();  // older than what was just taken
        return newest;
    }
    std::optional<Compiled> older = takeFrom(superseded_);
    if (superseded_ && superseded_->job->finished()) superseded_.reset();
    return older;
}

template <typename Tag>
void ProgramCompiler<Tag>::cancel() {
    // a compile that started cannot stop: it runs to the end into its own
    // result, which nobody reads
    if (last_ && !last_->job->started()) last_->job->cancel();
    last_.reset();
    superseded_.reset();
}

}  // namespace sdfwb::ui
