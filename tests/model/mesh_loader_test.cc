#include "edgefit/model/mesh_loader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>

namespace edgefit {
namespace {

const std::string kMeshes = EDGEFIT_SOURCE_DIR "/assets/models/meshes/";

bool HasVertex(const TriangleMesh& mesh, const Eigen::Vector3d& p, double tol = 1e-9) {
  for (const Eigen::Vector3d& v : mesh.vertices) {
    if ((v - p).norm() < tol) return true;
  }
  return false;
}

TEST(MeshLoaderTest, AsciiStlIsWeldedAndScaled) {
  TriangleMesh mesh;
  ASSERT_TRUE(LoadMesh(kMeshes + "tetra_ascii.stl", Eigen::Vector3d(2, 3, 4), &mesh).ok());
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.vertices.size(), 4u);  // 12 STL corners welded to 4.
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(2, 0, 0)));
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(0, 3, 0)));
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(0, 0, 4)));
}

TEST(MeshLoaderTest, BinaryStl) {
  // Two triangles of the unit square in binary STL, written here.
  const std::string path = ::testing::TempDir() + "/square_binary.stl";
  {
    std::ofstream out(path, std::ios::binary);
    char header[80] = "binary square";
    out.write(header, 80);
    const uint32_t n = 2;
    out.write(reinterpret_cast<const char*>(&n), 4);
    const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0},
                               {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& t : tris) {
      out.write(reinterpret_cast<const char*>(t), sizeof(t));
      const uint16_t attr = 0;
      out.write(reinterpret_cast<const char*>(&attr), 2);
    }
  }
  TriangleMesh mesh;
  const Status status = LoadMesh(path, Eigen::Vector3d::Ones(), &mesh);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_NEAR(mesh.SurfaceArea(), 1.0, 1e-12);
  std::remove(path.c_str());
}

TEST(MeshLoaderTest, ColladaKeepsZUpAppliesUnitAndNodeTransformSkipsCamera) {
  TriangleMesh mesh;
  const Status status = LoadMesh(kMeshes + "zup_mm.dae", Eigen::Vector3d::Ones(), &mesh);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(0, 0, 0.1), 1e-6));
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(1, 0, 0.1), 1e-6));
  EXPECT_TRUE(HasVertex(mesh, Eigen::Vector3d(0, 0, 0.6), 1e-6));
}

TEST(MeshLoaderTest, ObjIsTriangulated) {
  const std::string path = ::testing::TempDir() + "/quad.obj";
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4\n";
  }
  TriangleMesh mesh;
  ASSERT_TRUE(LoadMesh(path, Eigen::Vector3d::Ones(), &mesh).ok());
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_NEAR(mesh.SurfaceArea(), 2.0, 1e-12);
  std::remove(path.c_str());
}

TEST(MeshLoaderTest, MirroringScaleKeepsTrianglesOutward) {
  TriangleMesh mesh, mirrored;
  ASSERT_TRUE(LoadMesh(kMeshes + "tetra_ascii.stl", Eigen::Vector3d::Ones(), &mesh).ok());
  ASSERT_TRUE(LoadMesh(kMeshes + "tetra_ascii.stl", Eigen::Vector3d(-1, 1, 1), &mirrored).ok());
  auto signed_volume = [](const TriangleMesh& m) {
    double v = 0.0;
    for (const auto& t : m.triangles) {
      v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
    }
    return v;
  };
  EXPECT_NEAR(signed_volume(mesh), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(signed_volume(mirrored), 1.0 / 6.0, 1e-12);
}

TEST(MeshLoaderTest, MissingFileNamesIt) {
  TriangleMesh mesh;
  const Status status = LoadMesh("/nonexistent/part.stl", Eigen::Vector3d::Ones(), &mesh);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message().rfind("/nonexistent/part.stl: ", 0), 0u) << status.message();
  EXPECT_EQ(status.message().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace edgefit
