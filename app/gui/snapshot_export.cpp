#include "app/gui/snapshot_export.h"

#include <chrono>
#include <sstream>
#include <utility>

#include "app/backend.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "program/compile_scene.h"

namespace sdfwb::app::gui {
namespace {

// The job's body: renders and writes the file, returns the one-line outcome.
std::string exportSnapshot(const scene::Scene& scene, const SnapshotSettings& chosen, glcontext::GlContext* context,
                           jobs::Job& job) {
    try {
        // a wrong extension or a folder that cannot take the file fails before the render
        image::checkWritableFormat(chosen.path);
        io::checkCanCreate(chosen.path);
        auto start = std::chrono::steady_clock::now();
        program::Program program = program::compileScene(scene, {chosen.width, chosen.height, chosen.aa});
        std::unique_ptr<render::Backend> backend = makeBackend(chosen.gl ? Backend::Gl : Backend::Cpu, context);
        render::RenderControl control;
        control.cancel = &job.cancelFlag();
        control.progress = [&job](int done, int total) { job.setProgress(static_cast<double>(done) / total); };
        render::RenderOutcome result = backend->render(program, control);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (result.cancelled) return "snapshot cancelled; nothing written";
        image::writeImage(chosen.path, result.frame.color,
                          {{"sdfwb:scene", scene.name}, {"sdfwb:backend", backend->name()}});
        std::ostringstream text;
        text.precision(3);
        text << "wrote " << chosen.path << " (" << chosen.width << "x" << chosen.height << ", AA " << chosen.aa
             << ", " << seconds << " s)";
        return text.str();
    } catch (const std::exception& error) {
        return std::string("snapshot failed: ") + error.what();
    }
}

}  // namespace

SnapshotExport::~SnapshotExport() {
    cancel();
    queue_.reset();
}

void SnapshotExport::start(const scene::Scene& scene, const SnapshotSettings& chosen,
                           std::unique_ptr<glcontext::GlContext> shared) {
    if (running()) return;
    poll();
    context_ = std::move(shared);
    jobs::JobQueue::WorkerScope scope;
    if (context_) {
        scope = [context = context_.get()](const std::function<void()>& runJobs) {
            glcontext::ScopedCurrent current(*context);
            runJobs();
        };
    }
    queue_ = std::make_unique<jobs::JobQueue>(1, std::move(scope));
    outcome_ = std::make_shared<std::string>();
    job_ = queue_->submit([scene, chosen, context = context_.get(), outcome = outcome_](jobs::Job& job) {
        *outcome = exportSnapshot(scene, chosen, context, job);
    });
}

void SnapshotExport::cancel() {
    if (job_) job_->cancel();
}

std::string SnapshotExport::takeOutcome() {
    if (!job_ || !job_->finished() || !outcome_) return {};
    std::string outcome = std::exchange(*outcome_, {});
    if (outcome.empty() && job_->cancelled() && !job_->started()) outcome = "snapshot cancelled; nothing written";
    outcome_.reset();
    return outcome;
}

void SnapshotExport::poll() {
    if (job_ && job_->finished()) {
        queue_.reset();
        context_.reset();  // on the main thread, as GLFW requires
    }
}

}  // namespace sdfwb::app::gui
