#pragma once
// Mesh files: binary STL, Wavefront OBJ and binary PLY (little endian),
// chosen by the extension, written atomically (io/atomic_file.h) so a failure
// never leaves a partial file.

#include <filesystem>
#include <string>

#include "mesh/mesh.h"

namespace sdfwb::mesh {

enum class MeshFormat { Stl, Obj, Ply };

// The format of a path's extension (any case); throws std::invalid_argument
// "<path>: unsupported mesh format \".x\" (use .stl, .obj or .ply)".
MeshFormat meshFormatOf(const std::filesystem::path& path);

// The file's bytes.
std::string encodeMesh(const Mesh& mesh, MeshFormat format);

// Writes the mesh to `destination` in the format of its extension; throws
// std::runtime_error "cannot write <path>: ..." (nothing written then).
void writeMesh(const Mesh& mesh, const std::filesystem::path& destination);

}  // namespace sdfwb::mesh
