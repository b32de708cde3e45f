#include "edgefit/scene/tube_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh_checks.h"

namespace edgefit {
namespace {

TEST(TubeMeshTest, CatmullRomPassesThroughControlPointsWithBoundedSteps) {
  const std::vector<Eigen::Vector3d> control = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 1, 1}, {2, 1, 1}};
  const std::vector<Eigen::Vector3d> curve = CatmullRomCurve(control, 0.05);
  ASSERT_GT(curve.size(), 20u);
  for (size_t i = 1; i < curve.size(); ++i) {
    EXPECT_LE((curve[i] - curve[i - 1]).norm(), 0.1);  // chord steps, curve a bit longer
  }
  for (const Eigen::Vector3d& c : control) {
    double nearest = INFINITY;
    for (const Eigen::Vector3d& p : curve) nearest = std::min(nearest, (p - c).norm());
    EXPECT_LT(nearest, 1e-12);
  }
  EXPECT_EQ(curve.front(), control.front());
  EXPECT_EQ(curve.back(), control.back());
}

TEST(TubeMeshTest, SaggingSpanDroopsByTheSagAtMidSpan) {
  const std::vector<Eigen::Vector3d> span =
      SaggingSpan({0, 0, 1}, {2, 0, 1}, 0.2, -Eigen::Vector3d::UnitZ(), 5);
  ASSERT_EQ(span.size(), 5u);
  EXPECT_TRUE(span[0].isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(span[4].isApprox(Eigen::Vector3d(2, 0, 1)));
  EXPECT_NEAR(span[2].z(), 0.8, 1e-12);
  EXPECT_NEAR(span[1].z(), 1.0 - 4 * 0.2 * 0.25 * 0.75, 1e-12);
}

TEST(TubeMeshTest, TubeIsClosedWithTheRadiusAroundTheCenterline) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i <= 60; ++i) {
    const double a = 0.05 * i;
    line.emplace_back(std::cos(a), std::sin(a), 0.1 * a);  // a helix
  }
  const double radius = 0.02;
  const TriangleMesh tube = MakeTubeMesh(line, radius, 12);
  EXPECT_TRUE(testing_scene::AllFinite(tube));
  EXPECT_TRUE(testing_scene::IsClosed(tube));
  EXPECT_EQ(tube.vertices.size(), 61u * 12 + 2);
  // Ring vertices lie at the radius from their centre, perpendicular to the line.
  for (int i = 0; i <= 60; ++i) {
    for (int s = 0; s < 12; ++s) {
      EXPECT_NEAR((tube.vertices[i * 12 + s] - line[i]).norm(), radius, 1e-12);
    }
  }
  // Outward orientation: positive enclosed volume close to pi r^2 L.
  double volume = 0.0;
  for (const Eigen::Vector3i& t : tube.triangles) {
    volume += tube.vertices[t[0]].dot(tube.vertices[t[1]].cross(tube.vertices[t[2]])) / 6.0;
  }
  double length = 0.0;
  for (size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
  const double expected = M_PI * radius * radius * length * (12 / (2 * M_PI)) * std::sin(2 * M_PI / 12);
  EXPECT_NEAR(volume, expected, 0.02 * expected);
}

TEST(TubeMeshTest, DegenerateLineGivesEmptyTube) {
  EXPECT_TRUE(MakeTubeMesh({{0, 0, 0}, {0, 0, 0}}, 0.01, 8).empty());
}

}  // namespace
}  // namespace edgefit
