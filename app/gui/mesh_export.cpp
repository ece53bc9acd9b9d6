#include "app/gui/mesh_export.h"

#include <chrono>
#include <sstream>
#include <utility>

#include "io/atomic_file.h"
#include "mesh/mesh_files.h"

namespace sdfwb::app::gui {
namespace {

// The job's body: meshes and writes the file, returns the one-line outcome.
std::string exportMesh(const scene::Scene& scene, const MeshExportSettings& chosen, jobs::Job& job) {
    try {
        // a wrong extension or a folder that cannot take the file fails before the sampling
        mesh::meshFormatOf(chosen.path);
        io::checkCanCreate(chosen.path);
        auto start = std::chrono::steady_clock::now();
        mesh::Mesh result =
            mesh::extractMesh(scene, chosen.resolution, {&job.cancelFlag(), [&job](double f) { job.setProgress(f); }});
        mesh::writeMesh(result, chosen.path);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::ostringstream text;
        text.precision(3);
        text << "wrote " << chosen.path << " (" << result.triangles.size() << " triangles, resolution "
             << chosen.resolution << ", " << seconds << " s)";
        return text.str();
    } catch (const mesh::MeshCancelled&) {
        return "mesh export cancelled; nothing written";
    } catch (const std::exception& error) {
        return std::string("mesh export failed: ") + error.what();
    }
}

}  // namespace

void MeshExport::start(const scene::Scene& scene, const MeshExportSettings& chosen) {
    if (running()) return;
    outcome_ = std::make_shared<std::string>();
    job_ = queue_.submit(
        [scene, chosen, outcome = outcome_](jobs::Job& job) { *outcome = exportMesh(scene, chosen, job); });
}

void MeshExport::cancel() {
    if (job_) job_->cancel();
}

std::string MeshExport::takeOutcome() {
    if (!job_ || !job_->finished() || !outcome_) return {};
    std::string outcome = std::exchange(*outcome_, {});
    if (outcome.empty() && job_->cancelled()) outcome = "mesh export cancelled; nothing written";
    outcome_.reset();
    return outcome;
}

}  // namespace sdfwb::app::gui
