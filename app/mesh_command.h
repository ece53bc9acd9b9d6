#pragma once
// `sdf-workbench mesh`: a scene's surface as a triangle mesh file
// (mesh/extract_mesh.h, mesh/mesh_files.h).

#include <string>

#include <CLI/CLI.hpp>

namespace sdfwb::app {

struct MeshArguments {
    std::string scene;  // path, or "" for the embedded default scene
    std::string output;
    int resolution = 0;  // 0: mesh::kDefaultResolution
};

CLI::App* addMeshCommand(CLI::App& app, MeshArguments& arguments);

// Returns the process exit code; prints one-line errors to stderr.
int runMesh(const MeshArguments& arguments);

}  // namespace sdfwb::app
