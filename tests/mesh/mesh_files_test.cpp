// Mesh files (issue 13): each format holds the mesh's vertices and
// triangles, the extension chooses it, and a failed write leaves nothing.

#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "support/source_tree.h"

#include "mesh/mesh_files.h"

namespace sdfwb::mesh {
namespace {

namespace fs = std::filesystem;

Mesh tetrahedron() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

fs::path outputDir() {
    fs::path dir = fs::path(sdfwb::test::outputDir()) / "mesh_files";
    fs::create_directories(dir);
    return dir;
}

TEST(MeshFiles, TheExtensionChoosesTheFormat) {
    EXPECT_EQ(meshFormatOf("a/b.stl"), MeshFormat::Stl);
    EXPECT_EQ(meshFormatOf("b.OBJ"), MeshFormat::Obj);
    EXPECT_EQ(meshFormatOf("b.ply"), MeshFormat::Ply);
    try {
        meshFormatOf("out.png");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "out.png: unsupported mesh format \".png\" (use .stl, .obj or .ply)");
    }
}

TEST(MeshFiles, EachFormatHoldsTheTriangles) {
    Mesh m = tetrahedron();
    std::string stl = encodeMesh(m, MeshFormat::Stl);
    ASSERT_EQ(stl.size(), 84u + 50u * 4u);
    EXPECT_NE(stl.rfind("solid", 0), 0u);  // binary STL must not look like ASCII STL
    std::uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    EXPECT_EQ(count, 4u);
    float normal[3];  // the first triangle (0, 2, 1) faces -z
    std::memcpy(normal, stl.data() + 84, 12);
    EXPECT_FLOAT_EQ(normal[2], -1.0f);

    std::string obj = encodeMesh(m, MeshFormat::Obj);
    EXPECT_NE(obj.find("v 1 0 0\n"), std::string::npos);
    EXPECT_NE(obj.find("f 1 3 2\n"), std::string::npos);  // counted from 1

    std::string ply = encodeMesh(m, MeshFormat::Ply);
    std::string header = ply.substr(0, ply.find("end_header\n") + 11);
    EXPECT_NE(header.find("element vertex 4\n"), std::string::npos);
    EXPECT_NE(header.find("element face 4\n"), std::string::npos);
    EXPECT_EQ(ply.size(), header.size() + 4 * 12 + 4 * 13);
}

TEST(MeshFiles, AFailedWriteLeavesNoFile) {
    fs::path dir = outputDir();
    fs::path good = dir / "t.ply";
    writeMesh(tetrahedron(), good);
    EXPECT_EQ(fs::file_size(good), encodeMesh(tetrahedron(), MeshFormat::Ply).size());
    EXPECT_THROW(writeMesh(tetrahedron(), dir / "t.png"), std::invalid_argument);
    EXPECT_FALSE(fs::exists(dir / "t.png"));
    EXPECT_THROW(writeMesh(tetrahedron(), dir / "missing" / "t.stl"), std::runtime_error);
    for (const auto& entry : fs::directory_iterator(dir)) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
    }
}

}  // namespace
}  // namespace sdfwb::mesh
