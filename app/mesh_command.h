#pragma once
// `sdf-workbench mesh`: a scene's surface as a triangle mesh file
// (mesh/extract_mesh.h, mesh/mesh_files.h).

#include "app/mesh_arguments.h"

namespace sdfwb::app {

// Returns the process exit code; prints one-line errors to stderr.
int runMesh(const MeshArguments& arguments);

}  // namespace sdfwb::app
