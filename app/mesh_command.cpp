#include "app/mesh_command.h"

#include <cstdio>

#include "app/command_errors.h"
#include "app/output_paths.h"
#include "app/progress_bar.h"
#include "app/scene_source.h"
#include "mesh/extract_mesh.h"
#include "mesh/mesh_files.h"

namespace sdfwb::app {

int runMesh(const MeshArguments& a) {
    return runReportingErrors("mesh", [&] {
        // Everything the arguments can get wrong fails here, before any work.
        const int resolution = a.resolution == 0 ? mesh::kDefaultResolution : a.resolution;
        mesh::checkResolution(resolution);
        mesh::meshFormatOf(a.output);
        checkOutputs({{"the scene", a.scene}}, {{"-o", a.output}});
        scene::Scene scene = loadSceneArgument(a.scene);
        ProgressBar bar("meshing");
        mesh::Mesh result =
            mesh::extractMesh(scene, resolution,
                              {nullptr, [&](double fraction) { bar.update(static_cast<int>(fraction * 1000), 1000); }});
        mesh::writeMesh(result, a.output);
        std::printf("%s: %zu vertices, %zu triangles, voxel %.4g\n", a.output.c_str(), result.vertices.size(),
                    result.triangles.size(), result.voxelSize);
        return 0;
    });
}

}  // namespace sdfwb::app
