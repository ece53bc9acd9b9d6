#pragma once
// File > Export mesh: the scene's surface as an STL, OBJ or PLY file
// (mesh/extract_mesh.h), made by a background job with progress and cancel;
// the file is written atomically, so a failure or a cancel leaves none.

#include <memory>
#include <string>

#include "jobs/job_queue.h"
#include "mesh/extract_mesh.h"
#include "scene/scene.h"

namespace sdfwb::app::gui {

struct MeshExportSettings {
    std::string path = "mesh.stl";
    int resolution = mesh::kDefaultResolution;
};

class MeshExport {
public:
    // Starts an export; ignored while one runs. Never waits.
    void start(const scene::Scene& scene, const MeshExportSettings& settings);
    void cancel();
    bool running() const { return job_ && !job_->finished(); }
    double progress() const { return job_ ? job_->progress() : 0.0; }
    // The last export's outcome ("wrote PATH (N triangles, 1.2 s)", the error,
    // or "mesh export cancelled; nothing written"), once; "" otherwise.
    std::string takeOutcome();

    MeshExportSettings settings;  // what the dialog edits
    bool dialogOpen = false;

private:
    jobs::JobHandle job_;
    std::shared_ptr<std::string> outcome_;  // written by the job
    jobs::JobQueue queue_{1};               // last: stops before the rest goes
};

}  // namespace sdfwb::app::gui
