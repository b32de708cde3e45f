// Procedural builders: closed, outward-oriented, the expected volume, and
// sharp edges exactly where the CAD part has them.
#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/assets/loft_mesh.h"
#include "edgefit/assets/mesh_topology.h"
#include "edgefit/assets/motor_housing.h"
#include "edgefit/assets/perforated_plate.h"
#include "edgefit/assets/rectangular_loft.h"
#include "edgefit/assets/revolved_mesh.h"
#include "edgefit/model/sharp_edges.h"

namespace edgefit {
namespace {

void ExpectClosed(const TriangleMesh& mesh) {
  const MeshTopologyReport report = AnalyzeMeshTopology(mesh);
  EXPECT_TRUE(report.IsClosedAndOriented())
      << "open " << report.open_edges << ", non-manifold " << report.non_manifold_edges
      << ", misoriented " << report.misoriented_edges << ", degenerate "
      << report.degenerate_triangles;
  EXPECT_GT(SignedVolume(mesh), 0.0) << "normals point inwards";
}

TEST(ChamferedBoxTest, ClosedWithTheChamferedVolumeAndAllEdgesSharp) {
  const Eigen::Vector3d size(0.4, 0.3, 0.2);
  const double c = 0.02;
  const TriangleMesh box = MakeChamferedBox(size, c);
  ExpectClosed(box);
  const double volume = SignedVolume(box);
  EXPECT_LT(volume, size.prod());
  EXPECT_GT(volume, size.prod() - 0.5 * c * c * 4.0 * size.sum());
  // 26 faces: 6 sides, 12 edge chamfers, 8 corner facets. Each chamfer meets
  // its two faces at 45 deg (24 sharp edges); the corner facets meet the
  // chamfers at 30-55 deg. The quads' diagonals are flat.
  const MeshEdges edges = ExtractSharpEdges(box);
  EXPECT_EQ(edges.boundary.size(), 0u);
  EXPECT_GE(edges.sharp.size(), 24u);
  EXPECT_LE(edges.sharp.size(), 72u);  // Never a face diagonal: 4 * 8 ring edges + 3 * 8 sides.
}

TEST(RectangularLoftTest, TaperedCastingHasPlanarFlanks) {
  const TriangleMesh casting =
      MakeTaperedCasting({0.6, 0.4}, {0.3, 0.3}, {0.1, 0.0}, 0.5, 0.03, 0.01);
  ExpectClosed(casting);
  // Every triangle of a flank shares its plane with its quad partner: the
  // sharp edges are only section rims and corners, 8 per ring edge set.
  const MeshEdges edges = ExtractSharpEdges(casting);
  EXPECT_GE(edges.sharp.size(), 24u);
  EXPECT_LE(edges.sharp.size(), 8u * 3 + 8u * 4);
}

TEST(RevolvedMeshTest, ChamferedShaftVolumeAndRims) {
  const int segments = 256;
  const TriangleMesh shaft =
      MakeRevolvedSolid({{0.0, 0.09}, {0.01, 0.1}, {0.49, 0.1}, {0.5, 0.09}}, segments);
  ExpectClosed(shaft);
  // Frustum volumes of the polygonal section (area n/2 r^2 sin(2 pi / n)).
  const double k = 0.5 * segments * std::sin(2.0 * M_PI / segments);
  auto frustum = [k](double h, double r0, double r1) {
    return k * h / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1);
  };
  const double expected = 2.0 * frustum(0.01, 0.09, 0.1) + frustum(0.48, 0.1, 0.1);
  EXPECT_NEAR(SignedVolume(shaft), expected, 1e-12);
  // Four rims (two cap edges, two chamfer-to-body) of `segments` edges each.
  EXPECT_EQ(ExtractSharpEdges(shaft).sharp.size(), 4u * segments);
}

TEST(RevolvedMeshTest, ConeTipAndHexagon) {
  ExpectClosed(MakeRevolvedSolid({{0.0, 0.02}, {0.05, 0.02}, {0.08, 0.0}}, 32));
  const TriangleMesh hex = MakeRevolvedSolid({{0.0, 0.01}, {0.008, 0.01}}, 6, M_PI / 6.0);
  ExpectClosed(hex);
  EXPECT_EQ(ExtractSharpEdges(hex).sharp.size(), 18u);  // a hexagonal prism's edges
}

TEST(RevolvedMeshTest, TubeHasBoreAndGenusOne) {
  const int n = 64;
  const TriangleMesh tube = MakeTube(0.03, 0.05, 0.2, 0.0, n);
  ExpectClosed(tube);
  // Euler characteristic V - E + F = 0 for a torus.
  const MeshTopologyReport report = AnalyzeMeshTopology(tube);
  EXPECT_EQ(static_cast<int>(tube.vertices.size()) - report.edges +
                static_cast<int>(tube.triangles.size()),
            0);
  const double k = 0.5 * n * std::sin(2.0 * M_PI / n);
  EXPECT_NEAR(SignedVolume(tube), k * (0.05 * 0.05 - 0.03 * 0.03) * 0.2, 1e-12);
  ExpectClosed(MakeTube(0.03, 0.05, 0.2, 0.004, n));
}

TEST(PerforatedPlateTest, ClosedWithHolesRemovedFromTheVolume) {
  PerforatedPlateOptions options;
  options.size = {1.0, 0.6};
  options.thickness = 0.04;
  for (double x : {-0.4, 0.0, 0.4}) {
    for (double y : {-0.2, 0.2}) options.holes.push_back({{x, y}, 0.02});
  }
  const TriangleMesh plate = MakePerforatedPlate(options);
  ExpectClosed(plate);
  const int n = options.hole_segments;
  const double hole_area = 0.5 * n * std::sin(2.0 * M_PI / n) * 0.02 * 0.02;
  EXPECT_NEAR(SignedVolume(plate), (0.6 - 6.0 * hole_area) * 0.04, 1e-12);
  // Genus 6: V - E + F = 2 - 2 g.
  const MeshTopologyReport report = AnalyzeMeshTopology(plate);
  EXPECT_EQ(static_cast<int>(plate.vertices.size()) - report.edges +
                static_cast<int>(plate.triangles.size()),
            2 - 2 * 6);
  // Sharp: 12 plate edges split at grid lines plus two rims per hole; the
  // flat faces contribute none.
  const MeshEdges edges = ExtractSharpEdges(plate);
  EXPECT_GE(edges.sharp.size(), 12u + 6u * 2u * n);
}

TEST(MotorHousingTest, ClosedPartsWithRibsAndFlangeRims) {
  const TriangleMesh motor = MakeMotorHousing({});
  const MeshTopologyReport report = AnalyzeMeshTopology(motor);
  EXPECT_TRUE(report.IsClosedAndOriented());
  EXPECT_GT(SignedVolume(motor), M_PI * 0.08 * 0.08 * 0.2);
  EXPECT_GT(ExtractSharpEdges(motor).sharp.size(), 6u * 64u);
}

}  // namespace
}  // namespace edgefit
