// Mesh files: what is written reads back as the same triangles.
#include "MeshTesting.h"

using namespace sdfwb;
using namespace sdfwb::meshtest;

TEST_F(MeshTest, FilesReadBackTheSameTriangles) {
    const meshing::Mesh mesh = extract(source(kSphere), 24);
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("sdfwb-mesh-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (const char* name : {"m.ply", "m.obj", "m.stl", "m.glb"}) {
        ASSERT_TRUE(meshing::writeMesh(folder / name, mesh)) << name;
        auto back = meshing::readMesh(folder / name);
        ASSERT_TRUE(back) << name << ": " << back.error().message;
        EXPECT_EQ(back->triangleCount(), mesh.triangleCount()) << name;
        EXPECT_EQ(back->vertices.size(), mesh.vertices.size()) << name << " (equal positions merged)";
        EXPECT_TRUE(meshing::checkTopology(*back).watertight()) << name;
        EXPECT_TRUE(closedAndOutward(*back)) << name;
    }
    auto bad = meshing::writeMesh(folder / "m.xyz", mesh);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("unsupported mesh type"), std::string::npos);
    EXPECT_FALSE(meshing::readMesh(folder / "missing.ply"));
    std::filesystem::remove_all(folder);
}
