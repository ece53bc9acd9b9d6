#pragma once
// Builds GLSL-backend programs on a job-queue worker bound to its own context
// that shares objects with the caller's, and warms each up with a small draw
// (so llvmpipe's first-draw code generation also happens there). The caller
// (the GUI thread) polls for finished programs and adopts them into its own
// GlRenderer: it never waits on a compile.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl_renderer.h"
#include "glcontext/gl_context.h"
#include "jobs/job_queue.h"

namespace sdfwb::gl {

struct BuiltProgram {
    program::Program program;     // the request (its structure is what was built)
    glcontext::GlObject linked;   // empty when the build failed
    std::string error;            // the build report when it failed
    double seconds = 0;           // generation, compile, link and warm-up
};

class ProgramBuilder {
public:
    // `context` shares objects with the caller's context; the worker makes it
    // current on its own thread. The builder is destroyed on the thread that
    // made the context (GLFW needs the main thread), with the caller's
    // context current (programs nobody adopted are deleted then).
    explicit ProgramBuilder(std::unique_ptr<glcontext::GlContext> context);
    ~ProgramBuilder();
    ProgramBuilder(const ProgramBuilder&) = delete;
    ProgramBuilder& operator=(const ProgramBuilder&) = delete;

    // Queues a build of `program`'s structure unless one is queued, running
    // or delivered already. Older requests not started yet are dropped: only
    // the newest structure matters to an editor.
    void request(const program::Program& program);
    // A finished build, if any; the caller adopts `linked` (GlRenderer::adoptProgram).
    std::optional<BuiltProgram> take();
    // A build is queued or running.
    bool busy() const;
    // Blocks until no build is queued or running (tests; the UI polls).
    void wait() const;

private:
    struct Pending {
        std::uint64_t structure = 0;
        jobs::JobHandle job;
        std::shared_ptr<BuiltProgram> result;  // written by the job
    };

    std::unique_ptr<glcontext::GlContext> context_;
    GlRenderer* workerRenderer_ = nullptr;  // lives on the worker's stack
    std::vector<Pending> pending_;          // the caller's thread only
    jobs::JobQueue queue_;                  // last: its worker stops before the rest goes
};

}  // namespace sdfwb::gl
