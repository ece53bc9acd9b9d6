#include "app/mesh_arguments.h"

#include <string>

#include "mesh/extract_mesh.h"

namespace sdfwb::app {

CLI::App* addMeshCommand(CLI::App& app, MeshArguments& a) {
    CLI::App* mesh = app.add_subcommand("mesh", "Export a scene's surface as a triangle mesh (the ground left out)");
    mesh->add_option("scene", a.scene, "Scene file (JSON); omit for the built-in default scene");
    mesh->add_option("-o,--output", a.output, "Output mesh: .stl (binary), .obj or .ply (binary)")->required();
    mesh->add_option("--resolution", a.resolution,
                     "Voxels along the longest side of the scene's bounds, " + std::to_string(mesh::kMinResolution) +
                         "-" + std::to_string(mesh::kMaxResolution) + " (default " +
                         std::to_string(mesh::kDefaultResolution) + ")");
    return mesh;
}

}  // namespace sdfwb::app
