#include "edgefit/core/pose.h"

#include <gtest/gtest.h>

#include <cmath>

namespace edgefit {
namespace {

TEST(PoseTest, RpyMatchesUrdfConvention) {
  // URDF: rpy = (r, p, y) means Rz(y) * Ry(p) * Rx(r).
  const Eigen::Vector3d rpy(0.1, -0.4, 2.0);
  const Eigen::Matrix3d R = RotationFromRpy(rpy);
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  EXPECT_TRUE(R.isApprox(expected, 1e-12));
  EXPECT_TRUE(RpyFromRotation(R).isApprox(rpy, 1e-12));
  // Yaw of 90 degrees maps +X to +Y.
  EXPECT_TRUE((RotationFromRpy(Eigen::Vector3d(0, 0, M_PI / 2)) * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST(PoseTest, RpyRoundTripNearGimbalLock) {
  const Eigen::Vector3d rpy(0.0, M_PI / 2, 0.7);
  const Eigen::Matrix3d R = RotationFromRpy(rpy);
  EXPECT_TRUE(RotationFromRpy(RpyFromRotation(R)).isApprox(R, 1e-9));
}

TEST(PoseTest, FloorPose) {
  const Pose T = PoseFromXyYaw(1.0, 2.0, M_PI);
  EXPECT_TRUE((T * Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, 2, 0), 1e-12));
}

}  // namespace
}  // namespace edgefit
