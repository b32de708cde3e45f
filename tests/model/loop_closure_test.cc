#include "edgefit/model/loop_closure.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

const char kBalancerArm[] = EDGEFIT_SOURCE_DIR "/assets/models/balancer_arm.urdf";

class BalancerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const Status status = LoadKinematicModel(kBalancerArm, {}, &model_);
    ASSERT_TRUE(status.ok()) << status.message();
    j1_ = model_.JointIndex("joint_1");
    j2_ = model_.JointIndex("joint_2");
    cylinder_ = model_.JointIndex("cylinder_joint");
    piston_ = model_.JointIndex("piston_joint");
    rod_ = model_.JointIndex("rod_joint");
  }
  KinematicModel model_;
  int j1_, j2_, cylinder_, piston_, rod_;
};

TEST_F(BalancerTest, ParsedFromTheUrdfExtension) {
  ASSERT_EQ(model_.loop_closures().size(), 1u);
  const LoopClosure& closure = model_.loop_closures()[0];
  EXPECT_EQ(closure.name, "balancer");
  EXPECT_EQ(model_.links()[closure.link_a].name, "piston");
  EXPECT_EQ(model_.links()[closure.link_b].name, "link_2");
  EXPECT_TRUE(closure.p_link_b.isApprox(Eigen::Vector3d(0.3, 0, 0)));
  EXPECT_EQ(closure.joints, (std::vector<int>{cylinder_, piston_}));
  EXPECT_EQ(model_.joints()[cylinder_].loop_closure, 0);
  EXPECT_EQ(model_.joints()[rod_].mimic_joint, piston_);
  EXPECT_EQ(model_.IndependentJoints(), (std::vector<int>{j1_, j2_}));
}

TEST_F(BalancerTest, SolvedJointsMatchClosedFormForManyMainJointValues) {
  const Eigen::Vector3d C(0.4, 0.0, 0.3);  // Cylinder pivot in link_1.
  for (double q1 : {0.0, 1.3}) {
    for (double q2 : {-1.0, -0.6, -0.2, 0.0, 0.35, 0.8, 1.0}) {
      std::vector<double> q = model_.ZeroJoints();
      q[j1_] = q1;
      q[j2_] = q2;
      const Status status = model_.ResolveDependentJoints(&q, 1e-9);
      ASSERT_TRUE(status.ok()) << status.message();
      const Eigen::Vector3d P(0.3 * std::cos(q2), 0.0, 1.0 - 0.3 * std::sin(q2));
      EXPECT_NEAR(q[piston_], (P - C).norm(), 1e-9) << "q2 " << q2;
      EXPECT_NEAR(q[cylinder_], std::atan2(P.x() - C.x(), P.z() - C.z()), 1e-9) << "q2 " << q2;
      EXPECT_LT(LoopClosureResidual(model_, model_.loop_closures()[0], q).norm(), 1e-9);
      // Mimic of a loop-driven joint follows the solved value.
      EXPECT_DOUBLE_EQ(q[rod_], 0.5 * q[piston_] + 0.01);
    }
  }
}

TEST_F(BalancerTest, WarmStartFromPreviousSolution) {
  std::vector<double> q = model_.ZeroJoints();
  for (double q2 = -1.0; q2 <= 1.0; q2 += 0.05) {  // A sweep, as the fitter does.
    q[j2_] = q2;
    ASSERT_TRUE(model_.ResolveDependentJoints(&q, 1e-9).ok());
    EXPECT_LT(LoopClosureResidual(model_, model_.loop_closures()[0], q).norm(), 1e-9);
  }
}

TEST_F(BalancerTest, UnreachableClosureIsAnErrorNamingIt) {
  KinematicModel model = model_;
  Joint& piston = model.mutable_joints()[piston_];
  piston.upper = 0.3;  // Too short for the far poses.
  std::vector<double> q = model.ZeroJoints();
  q[j2_] = -1.0;
  const Status status = model.ResolveDependentJoints(&q, 1e-6);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("'balancer'"), std::string::npos) << status.message();
  EXPECT_LE(q[piston_], 0.3);  // Limits respected, best effort kept.
}

TEST_F(BalancerTest, AddLoopClosureValidatesNames) {
  KinematicModel model = model_;
  LoopClosureSpec spec;
  spec.name = "bad";
  spec.link_a = "piston";
  spec.link_b = "nowhere";
  spec.joints = {"piston_joint"};
  Status status = AddLoopClosure(spec, &model);
  EXPECT_EQ(status.message(), "loop_closure 'bad': unknown link_b 'nowhere'");
  spec.link_b = "link_2";
  spec.joints = {"rod_joint"};
  status = AddLoopClosure(spec, &model);
  EXPECT_EQ(status.message(), "loop_closure 'bad': joint 'rod_joint' is already a mimic joint");
}

}  // namespace
}  // namespace edgefit
