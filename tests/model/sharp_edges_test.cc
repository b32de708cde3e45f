#include "edgefit/model/sharp_edges.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/model/primitive_meshes.h"

namespace edgefit {
namespace {

TEST(SharpEdgesTest, BoxHasTwelveSharpEdges) {
  const MeshEdges edges = ExtractSharpEdges(MakeBoxMesh(Eigen::Vector3d(1, 2, 3)));
  EXPECT_EQ(edges.sharp.size(), 12u);  // The 6 face diagonals are flat.
  EXPECT_TRUE(edges.boundary.empty());
  EXPECT_EQ(edges.non_manifold, 0);
  double total_length = 0.0;
  for (const EdgeSegment& e : edges.sharp) total_length += (e.b - e.a).norm();
  EXPECT_NEAR(total_length, 4 * (1 + 2 + 3), 1e-12);
  // A 95 deg threshold keeps none.
  EXPECT_TRUE(ExtractSharpEdges(MakeBoxMesh(Eigen::Vector3d::Ones()), {95.0}).sharp.empty());
}

TEST(SharpEdgesTest, FineCylinderOnlyRimCircles) {
  const int segments = 64;
  const MeshEdges edges = ExtractSharpEdges(MakeCylinderMesh(0.2, 1.0, segments));
  ASSERT_EQ(edges.sharp.size(), 2u * segments);
  for (const EdgeSegment& e : edges.sharp) {
    EXPECT_NEAR(std::abs(e.a.z()), 0.5, 1e-12);
    EXPECT_NEAR(e.a.z(), e.b.z(), 1e-12);
    EXPECT_NEAR(e.a.head<2>().norm(), 0.2, 1e-12);
  }
  EXPECT_TRUE(edges.boundary.empty());
}

TEST(SharpEdgesTest, FineSphereHasNone) {
  EXPECT_EQ(ExtractSharpEdges(MakeSphereMesh(1.0, 3)).sharp.size(), 0u);
  // A bare icosahedron has 30 edges at 41.8 deg.
  EXPECT_EQ(ExtractSharpEdges(MakeSphereMesh(1.0, 0)).sharp.size(), 30u);
}

TEST(SharpEdgesTest, OpenBoundaryFlaggedSeparately) {
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const MeshEdges edges = ExtractSharpEdges(square);
  EXPECT_EQ(edges.boundary.size(), 4u);
  EXPECT_TRUE(edges.sharp.empty());
}

}  // namespace
}  // namespace edgefit
