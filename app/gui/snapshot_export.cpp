#include "app/gui/snapshot_export.h"

#include <chrono>
#include <utility>
#include <sstream>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "image/image_io.h"
#include "program/compile_scene.h"

namespace sdfwb::app::gui {

SnapshotExport::~SnapshotExport() {
    cancel_ = true;
    if (worker_.joinable()) worker_.join();
}

void SnapshotExport::start(const scene::Scene& scene, const SnapshotSettings& chosen,
                           std::unique_ptr<glcontext::GlContext> shared) {
    if (running_) return;
    poll();
    if (worker_.joinable()) worker_.join();
    context_ = std::move(shared);
    running_ = true;
    cancel_ = false;
    progress_ = 0.0;
    worker_ = std::thread([this, scene, chosen] {
        std::string outcome;
        try {
            image::checkWritableFormat(chosen.path);
            auto start = std::chrono::steady_clock::now();
            program::Program program = program::compileScene(scene, {chosen.width, chosen.height, chosen.aa});
            auto progress = [this](int done, int total) { progress_ = static_cast<double>(done) / total; };
            image::Frame frame;
            bool cancelled = false;
            if (chosen.gl) {
                glcontext::ScopedCurrent current(*context_);
                gl::GlRenderer renderer(context_->gl());
                gl::GlRenderOutcome result = renderer.render(program, {256, &cancel_, progress});
                frame = std::move(result.frame);
                cancelled = result.cancelled;
            } else {
                cpu::RenderControl control;
                control.cancel = &cancel_;
                control.progress = progress;
                cpu::RenderOutcome result = cpu::renderCpu(program, control);
                frame = std::move(result.frame);
                cancelled = result.cancelled;
            }
            double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (cancelled) {
                outcome = "snapshot cancelled; nothing written";
            } else {
                image::writeImage(chosen.path, frame.color,
                                  {{"sdfwb:scene", scene.name}, {"sdfwb:backend", chosen.gl ? "gl" : "cpu"}});
                std::ostringstream text;
                text.precision(3);
                text << "wrote " << chosen.path << " (" << chosen.width << "x" << chosen.height << ", AA "
                     << chosen.aa << ", " << seconds << " s)";
                outcome = text.str();
            }
        } catch (const std::exception& error) {
            outcome = std::string("snapshot failed: ") + error.what();
        }
        std::lock_guard lock(mutex_);
        outcome_ = outcome;
        running_ = false;
    });
}

std::string SnapshotExport::takeOutcome() {
    std::lock_guard lock(mutex_);
    return std::exchange(outcome_, {});
}

void SnapshotExport::poll() {
    if (!running_ && worker_.joinable()) {
        worker_.join();
        context_.reset();  // on the main thread, as GLFW requires
    }
}

}  // namespace sdfwb::app::gui
