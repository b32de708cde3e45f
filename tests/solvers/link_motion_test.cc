// LinkMotion: joint poses and the projection of a free pose onto the joint
// (paper Sec. 5.2.2 and 6.2.2).
#include "solvers/registration/link_motion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace edgefit {
namespace {

LinkMotion Revolute() {
  Joint joint;
  joint.name = "j";
  joint.type = JointType::kRevolute;
  joint.T_parent_joint = PoseFromXyzRpy({0.1, 0.2, 0.3}, {0.2, -0.1, 0.5});
  joint.axis = Eigen::Vector3d(1, 2, 2) / 3.0;
  joint.has_limits = true;
  joint.lower = -2.0;
  joint.upper = 2.5;
  return LinkMotion::FromJoint(joint, PoseFromXyzRpy({1, -1, 0.5}, {0, 0, 1.0}));
}

LinkMotion Prismatic() {
  LinkMotion motion = Revolute();
  motion.type = LinkMotion::Type::kPrismatic;
  motion.lower = -0.4;
  motion.upper = 0.6;
  return motion;
}

TEST(LinkMotionTest, RevolutePoseAndProjectionRoundTrip) {
  const LinkMotion motion = Revolute();
  for (const double theta : {-1.9, -0.3, 0.0, 0.7, 2.4}) {
    const Pose T = motion.PoseAt(theta);
    EXPECT_NEAR(motion.Project(T, 0.0), theta, 1e-12);
    // The axis points stay where the parent puts them.
    const Eigen::Vector3d on_axis = 0.7 * motion.axis_joint;
    EXPECT_LT((T * on_axis - motion.T_world_joint * on_axis).norm(), 1e-12);
  }
}

TEST(LinkMotionTest, PrismaticPoseAndProjectionRoundTrip) {
  const LinkMotion motion = Prismatic();
  for (const double d : {-0.35, 0.0, 0.05, 0.55}) {
    const Pose T = motion.PoseAt(d);
    EXPECT_NEAR(motion.Project(T, 0.0), d, 1e-12);
    EXPECT_TRUE(T.linear().isApprox(motion.T_world_joint.linear(), 1e-12));
  }
}

// A pose off the joint (swing about another axis, shift off the axis)
// projects to the twist angle about the joint axis.
TEST(LinkMotionTest, ProjectionDropsSwingAndOffset) {
  const LinkMotion motion = Revolute();
  const double theta = 0.8;
  const Eigen::Vector3d perpendicular = motion.axis_joint.unitOrthogonal();
  Pose T = motion.T_world_joint * Eigen::AngleAxisd(0.01, perpendicular) *
           Eigen::AngleAxisd(theta, motion.axis_joint);
  T.translation() += Eigen::Vector3d(0.002, -0.001, 0.003);
  EXPECT_NEAR(motion.Project(T, 0.0), theta, 1e-4);
}

TEST(LinkMotionTest, RevoluteBranchNearestReferenceAndLimits) {
  LinkMotion motion = Revolute();
  motion.has_limits = false;  // continuous
  const Pose T = motion.PoseAt(3.0);
  EXPECT_NEAR(motion.Project(T, 0.0), 3.0, 1e-12);
  EXPECT_NEAR(motion.Project(T, 9.0), 3.0 + 2.0 * M_PI, 1e-12);
  EXPECT_NEAR(motion.Project(T, -3.0), 3.0 - 2.0 * M_PI, 1e-12);
  motion.has_limits = true;  // [-2, 2.5]: 3.0 is clamped
  EXPECT_DOUBLE_EQ(motion.Project(T, 0.0), 2.5);
  EXPECT_DOUBLE_EQ(motion.Clamp(-7.0), -2.0);
}

TEST(LinkMotionTest, FreeMotion) {
  LinkMotion motion = LinkMotion::Free();
  EXPECT_FALSE(motion.constrained());
  EXPECT_TRUE(Revolute().constrained());
  EXPECT_EQ(motion.Project(PoseFromXyzRpy({1, 2, 3}, {0.1, 0.2, 0.3}), 0.5), 0.0);
}

}  // namespace
}  // namespace edgefit
