// The body helpers of the fit (solvers/joints/body.h): the
// Sec. 5.2.1 symmetry test and the round part a symmetric parent carries
// of a child whose value is not fitted yet.
#include "solvers/joints/body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/model/primitive_meshes.h"

namespace edgefit {
namespace {

constexpr double kRadius = 0.08;  // [m]

SurfaceSamples Samples(const TriangleMesh& mesh) { return SampleMeshSurface(mesh, 0.003, 7); }

// A flange: a cylinder about z; with a box to one side, a flange under a gun.
TriangleMesh Flange() { return MakeCylinderMesh(kRadius, 0.10, 64); }

TriangleMesh FlangeWithBox() {
  TriangleMesh mesh = Flange();
  mesh.Append(MakeBoxMesh({0.20, 0.10, 0.10}), PoseFromXyzRpy({0.20, 0, 0.10}, {0, 0, 0}));
  return mesh;
}

TEST(RobotBodiesTest, CylinderIsSymmetricAboutItsAxisOnly) {
  const SurfaceSamples cylinder = Samples(Flange());
  EXPECT_TRUE(IsRotationallySymmetric(cylinder, Eigen::Vector3d::UnitZ(), 0.9));
  EXPECT_FALSE(IsRotationallySymmetric(cylinder, Eigen::Vector3d::UnitX(), 0.9));
  EXPECT_FALSE(IsRotationallySymmetric(Samples(FlangeWithBox()), Eigen::Vector3d::UnitZ(), 0.9));
}

// The round part about z of a flange with a box beside it is the flange:
// nearly all of its samples, none of the box's beyond the flange's rim.
TEST(RobotBodiesTest, RoundPartIsTheFlange) {
  const SurfaceSamples flange = Samples(Flange());
  const SurfaceSamples round = RoundPart(Samples(FlangeWithBox()), Eigen::Vector3d::UnitZ());
  ASSERT_EQ(round.normals.size(), round.points.size());
  size_t outside = 0;
  for (const Eigen::Vector3f& p : round.points) {
    outside += std::hypot(p.x(), p.y()) > kRadius + 0.005;
  }
  EXPECT_EQ(outside, 0u);
  EXPECT_GT(static_cast<double>(round.size()), 0.8 * static_cast<double>(flange.size()));
  EXPECT_TRUE(RoundPart(flange, Eigen::Vector3d::UnitX()).size() < flange.size() / 5);
}

TEST(RobotBodiesTest, PosedSamplesAreMovedAndTurned) {
  const SurfaceSamples flange = Samples(Flange());
  const Pose T = PoseFromXyzRpy({1, 2, 3}, {0, M_PI / 2, 0});
  SurfaceSamples out;
  AppendPosedSamples(flange, T, &out);
  ASSERT_EQ(out.size(), flange.size());
  for (size_t i = 0; i < out.size(); i += 97) {
    EXPECT_TRUE(out.points[i].isApprox((T * flange.points[i].cast<double>()).cast<float>(), 1e-5f));
    EXPECT_TRUE(out.normals[i].isApprox(
        (T.linear() * flange.normals[i].cast<double>()).cast<float>(), 1e-5f));
    EXPECT_EQ(out.triangles[i], -1);
  }
}

}  // namespace
}  // namespace edgefit
