#pragma once
// Builds GLSL-backend programs on a worker thread with its own context that
// shares objects with the caller's, and warms each up with a small draw (so
// llvmpipe's first-draw code generation also happens there). The caller
// (the GUI thread) polls for finished programs and adopts them into its own
// GlRenderer: it never waits on a compile.

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "gl/gl_renderer.h"
#include "glcontext/gl_context.h"

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
    // made the context (GLFW needs the main thread), after the worker stopped.
    explicit ProgramBuilder(std::unique_ptr<glcontext::GlContext> context);
    ~ProgramBuilder();
    ProgramBuilder(const ProgramBuilder&) = delete;
    ProgramBuilder& operator=(const ProgramBuilder&) = delete;

    // Queues a build of `program`'s structure unless one is queued, running
    // or delivered already. Older queued requests are dropped: only the
    // newest structure matters to an editor.
    void request(const program::Program& program);
    // A finished build, if any; the caller adopts `linked` (GlRenderer::adoptProgram).
    std::optional<BuiltProgram> take();
    // A build is queued or running.
    bool busy() const;

private:
    void run();

    std::unique_ptr<glcontext::GlContext> context_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<program::Program> queued_;
    std::optional<std::uint64_t> running_;
    std::deque<BuiltProgram> done_;
    bool stop_ = false;
    std::thread worker_;
};

}  // namespace sdfwb::gl
