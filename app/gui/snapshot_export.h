#pragma once
// Snapshot export: the current view at a chosen size and AA, through either
// backend, written to PNG or EXR as a background job with progress and
// cancel. The GL backend renders on a worker bound to a context sharing the
// window's.

#include <memory>
#include <string>

#include "glcontext/gl_context.h"
#include "jobs/job_queue.h"
#include "scene/scene.h"

namespace sdfwb::app::gui {

struct SnapshotSettings {
    std::string path = "snapshot.png";
    int width = 1920;
    int height = 1080;
    int aa = 2;
    bool gl = false;  // GLSL backend, else CPU
};

class SnapshotExport {
public:
    SnapshotExport() = default;
    // Cancels a running export and waits for it (on the main thread).
    ~SnapshotExport();

    // Starts an export (`shared` must share the window's context for GL;
    // created on the main thread). Ignored while one runs.
    void start(const scene::Scene& scene, const SnapshotSettings& settings,
               std::unique_ptr<glcontext::GlContext> shared);
    void cancel();
    bool running() const { return job_ && !job_->finished(); }
    double progress() const { return job_ ? job_->progress() : 0.0; }
    // The outcome of the last export ("wrote PATH (W x H, 1.2 s)" or the
    // error), once; "" otherwise.
    std::string takeOutcome();
    // Releases a finished export's worker and context (call each frame, on
    // the main thread, as GLFW requires).
    void poll();

    SnapshotSettings settings;  // what the dialog edits
    bool dialogOpen = false;

private:
    std::unique_ptr<glcontext::GlContext> context_;
    std::unique_ptr<jobs::JobQueue> queue_;  // after the context: stops first
    jobs::JobHandle job_;
    std::shared_ptr<std::string> outcome_;   // written by the job
};

}  // namespace sdfwb::app::gui
