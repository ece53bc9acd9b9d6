#include "mesh/mesh_files.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "io/atomic_file.h"

namespace sdfwb::mesh {
namespace {

// The binary formats are little endian, as is every machine this builds for.
static_assert(std::endian::native == std::endian::little, "binary STL and PLY are written in the host's byte order");

template <class T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

void putVec(std::string& out, const glm::vec3& v) {
    put(out, v.x);
    put(out, v.y);
    put(out, v.z);
}

std::string stl(const Mesh& mesh) {
    std::string out(80, ' ');
    out.replace(0, 31, "binary STL written by sdf-workb");  // must not begin with "solid": that is ASCII STL
    put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    out.reserve(out.size() + 50 * mesh.triangles.size());
    for (const glm::u32vec3& t : mesh.triangles) {
        const glm::vec3 &a = mesh.vertices[t.x], &b = mesh.vertices[t.y], &c = mesh.vertices[t.z];
        glm::vec3 n = glm::cross(b - a, c - a);
        float length = glm::length(n);
        putVec(out, length > 0 ? n / length : glm::vec3(0));
        putVec(out, a);
        putVec(out, b);
        putVec(out, c);
        put(out, std::uint16_t{0});
    }
    return out;
}

std::string obj(const Mesh& mesh) {
    std::string out = "# written by sdf-workbench\n";
    char line[96];
    for (const glm::vec3& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v.x, v.y, v.z);
        out += line;
    }
    for (const glm::u32vec3& t : mesh.triangles) {  // OBJ counts from 1
        std::snprintf(line, sizeof line, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
        out += line;
    }
    return out;
}

std::string ply(const Mesh& mesh) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by sdf-workbench\nelement vertex " +
                      std::to_string(mesh.vertices.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(mesh.triangles.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const glm::vec3& v : mesh.vertices) putVec(out, v);
    for (const glm::u32vec3& t : mesh.triangles) {
        put(out, std::uint8_t{3});
        put(out, t.x);
        put(out, t.y);
        put(out, t.z);
    }
    return out;
}

}  // namespace

MeshFormat meshFormatOf(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".ply") return MeshFormat::Ply;
    throw std::invalid_argument(path.string() + ": unsupported mesh format \"" + path.extension().string() +
                                "\" (use .stl, .obj or .ply)");
}

std::string encodeMesh(const Mesh& mesh, MeshFormat format) {
    switch (format) {
    case MeshFormat::Stl: return stl(mesh);
    case MeshFormat::Obj: return obj(mesh);
    case MeshFormat::Ply: return ply(mesh);
    }
    throw std::logic_error("unknown mesh format");
}

void writeMesh(const Mesh& mesh, const std::filesystem::path& destination) {
    io::writeTextAtomically(destination, encodeMesh(mesh, meshFormatOf(destination)));
}

}  // namespace sdfwb::mesh
