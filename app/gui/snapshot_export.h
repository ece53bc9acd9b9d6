#pragma once
// Snapshot export: the current view at a chosen size and AA, through either
// backend, written to PNG or EXR on a worker thread with progress and cancel.
// The GL backend renders on a worker with a context sharing the window's.

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "glcontext/gl_context.h"
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
    ~SnapshotExport();

    // Starts an export (`shared` must share the window's context for GL;
    // created on the main thread). Ignored while one runs.
    void start(const scene::Scene& scene, const SnapshotSettings& settings,
               std::unique_ptr<glcontext::GlContext> shared);
    void cancel() { cancel_ = true; }
    bool running() const { return running_; }
    double progress() const { return progress_; }
    // The outcome of the last export ("wrote PATH (W x H, 1.2 s)" or the
    // error), once; "" otherwise.
    std::string takeOutcome();
    // Joins a finished worker (call each frame).
    void poll();

    SnapshotSettings settings;  // what the dialog edits
    bool dialogOpen = false;

private:
    std::atomic<bool> running_{false};
    std::atomic<bool> cancel_{false};
    std::atomic<double> progress_{0.0};
    std::mutex mutex_;
    std::string outcome_;
    std::unique_ptr<glcontext::GlContext> context_;
    std::thread worker_;
};

}  // namespace sdfwb::app::gui
