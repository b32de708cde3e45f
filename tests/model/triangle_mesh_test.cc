#include "edgefit/model/triangle_mesh.h"

#include <gtest/gtest.h>

#include "edgefit/model/primitive_meshes.h"

namespace edgefit {
namespace {

// Sum over triangles of n * (area-weighted) centroid = volume * 3 for a
// closed, outward mesh (divergence theorem), so the sign checks orientation.
double SignedVolume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  }
  return v;
}

TEST(TriangleMeshTest, BoxAreaVolumeAndBoundingBox) {
  const TriangleMesh box = MakeBoxMesh(Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_NEAR(box.SurfaceArea(), 2 * (2.0 + 3.0 + 6.0), 1e-12);
  EXPECT_NEAR(SignedVolume(box), 6.0, 1e-12);
  const Eigen::AlignedBox3d bb = box.BoundingBox(Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0)));
  EXPECT_TRUE(bb.min().isApprox(Eigen::Vector3d(0.5, -1.0, -1.5)));
  EXPECT_TRUE(bb.max().isApprox(Eigen::Vector3d(1.5, 1.0, 1.5)));
  EXPECT_TRUE(TriangleMesh().BoundingBox().isEmpty());
}

TEST(TriangleMeshTest, CylinderAndSphereAreOutwardAndClose) {
  const TriangleMesh cylinder = MakeCylinderMesh(0.5, 2.0, 256);
  EXPECT_NEAR(SignedVolume(cylinder), M_PI * 0.25 * 2.0, 2e-3);
  EXPECT_NEAR(cylinder.SurfaceArea(), 2 * M_PI * 0.5 * 2.0 + 2 * M_PI * 0.25, 5e-3);
  const TriangleMesh sphere = MakeSphereMesh(2.0, 4);
  EXPECT_EQ(sphere.triangles.size(), 20u * 256u);
  EXPECT_NEAR(SignedVolume(sphere), 4.0 / 3.0 * M_PI * 8.0, 0.1);  // Inscribed: 0.2% less.
  for (const Eigen::Vector3d& v : sphere.vertices) EXPECT_NEAR(v.norm(), 2.0, 1e-12);
}

TEST(TriangleMeshTest, AppendTransformsAndOffsetsIndices) {
  TriangleMesh a = MakeBoxMesh(Eigen::Vector3d::Ones());
  a.Append(MakeBoxMesh(Eigen::Vector3d::Ones()), Eigen::Isometry3d(Eigen::Translation3d(0, 0, 5)));
  EXPECT_EQ(a.vertices.size(), 16u);
  EXPECT_EQ(a.triangles[12], a.triangles[0] + Eigen::Vector3i::Constant(8));
  EXPECT_NEAR(a.BoundingBox().max().z(), 5.5, 1e-12);
}

TEST(TriangleMeshTest, WeldMergesIdenticalCornersAndDropsDegenerates) {
  // Two triangles sharing an edge, written STL-style with separate corners,
  // plus one triangle that collapses to a line.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                   {2, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  EXPECT_EQ(WeldIdenticalVertices(&mesh), 1);
  EXPECT_EQ(mesh.vertices.size(), 6u);  // 4 unique used corners + (2,0,0), (3,0,0).
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices[mesh.triangles[0][1]], mesh.vertices[mesh.triangles[1][0]]);
  EXPECT_EQ(mesh.triangles[0][1], mesh.triangles[1][0]);
}

}  // namespace
}  // namespace edgefit
