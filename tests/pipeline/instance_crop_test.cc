// The instance crop: the model's reach bounds every posture's surfaces, and
// a cropped scan keeps exactly the rays that pass near the centres.
#include "edgefit/pipeline/instance_crop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/bundled_robot_test_util.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace {

TEST(InstanceCropTest, ReachBoundsEveryPostureOfTheRobotWithItsGun) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun("", &model, &q);
  const double reach = ModelReach(model);
  std::mt19937 rng(4);
  double farthest = 0.0;
  for (int draw = 0; draw < 100; ++draw) {
    for (size_t j = 0; j < model.joints().size(); ++j) {
      const Joint& joint = model.joints()[j];
      if (joint.IsIndependent()) q[j] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
    }
    ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
    const std::vector<Pose> T_base_link = model.ForwardKinematics(q, Pose::Identity());
    for (size_t k = 0; k < model.links().size(); ++k) {
      for (const Eigen::Vector3d& v : model.links()[k].mesh.vertices) {
        farthest = std::max(farthest, (T_base_link[k] * v).norm());
      }
    }
  }
  EXPECT_GE(reach, farthest);
  EXPECT_LT(reach, 1.6 * farthest) << "a bound, but not a loose one";
}

TEST(InstanceCropTest, KeepsTheRaysThatPassNearACentre) {
  testing::SyntheticScanOptions o;
  o.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(1.0, -2.0, 1.5), Eigen::Vector3d(0, 0, 0.4));
  ScanSet scans;
  scans.scans.push_back(testing::MakeSyntheticScan(testing::RoomScene(), o));
  const Eigen::Vector3d center(3.0, 1.0, 0.5);
  const double radius = 1.0;
  const ScanSet cropped = CropToRays(scans, {center}, radius);
  const OrganizedScan& in = scans.scans[0];
  const OrganizedScan& out = cropped.scans[0];
  const Eigen::Vector3d origin = in.T_world_scanner().translation();
  size_t kept = 0, checked = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    if (!in.IsValid(i)) continue;
    const Eigen::Vector3d d = (in.PointWorld(i) - origin).normalized();
    const double along = (center - origin).dot(d);
    const double miss = along > 0 ? ((center - origin) - along * d).norm() : (center - origin).norm();
    if (std::abs(miss - radius) < 1e-4) continue;  // float rounding at the boundary
    ++checked;
    EXPECT_EQ(out.IsValid(i), miss < radius) << "cell " << i << " passes " << miss << " m from the centre";
    kept += out.IsValid(i);
  }
  EXPECT_GT(kept, 100u);
  EXPECT_LT(kept, checked / 2);
  // A scanner inside the sphere keeps everything.
  EXPECT_EQ(CropToRays(scans, {origin + Eigen::Vector3d(0.5, 0, 0)}, radius).TotalValid(), scans.TotalValid());
}

}  // namespace
}  // namespace edgefit
