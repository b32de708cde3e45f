// Known joints (frozen_joints.h): the frozen model places every link as the
// original does at the known values, its other joints still move, and a
// bad known joint is refused naming it.
#include "edgefit/model/frozen_joints.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

TEST(FrozenJointsTest, FrozenModelPlacesTheLinksAsTheOriginal) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun(
      "joint_1=0.7,joint_2=0.45,joint_3=-0.2,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
      &model, &q);
  const KnownJoints known = {{"joint_2", 0.45}, {"joint_4", -0.5}};
  KinematicModel frozen;
  ASSERT_TRUE(FreezeJoints(model, known, &frozen).ok());
  EXPECT_FALSE(frozen.joints()[model.JointIndex("joint_2")].IsMoving());
  EXPECT_TRUE(frozen.joints()[model.JointIndex("joint_3")].IsMoving());
  EXPECT_EQ(frozen.IndependentJoints().size(), model.IndependentJoints().size() - 2);
  std::vector<double> q_frozen = q;  // the frozen joints' entries are ignored
  q_frozen[model.JointIndex("joint_2")] = 0.0;
  q_frozen[model.JointIndex("joint_4")] = 0.0;
  const Pose T = PoseFromXyzRpy({1.0, -2.0, 0.3}, {0.1, -0.2, 0.5});
  const std::vector<Pose> original = model.ForwardKinematics(q, T);
  const std::vector<Pose> held = frozen.ForwardKinematics(q_frozen, T);
  for (size_t l = 0; l < original.size(); ++l) {
    EXPECT_TRUE(original[l].matrix().isApprox(held[l].matrix(), 1e-12)) << model.links()[l].name;
  }
  SetKnownJoints(model, known, &q_frozen);
  EXPECT_EQ(q_frozen, q);
}

TEST(FrozenJointsTest, EveryJointKnownLeavesOneRigidBody) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun("joint_2=0.3", &model, &q);
  KnownJoints all;
  for (const int j : model.IndependentJoints()) all.emplace_back(model.joints()[j].name, q[j]);
  KinematicModel frozen;
  ASSERT_TRUE(FreezeJoints(model, all, &frozen).ok());
  EXPECT_TRUE(frozen.IndependentJoints().empty());
  for (const Joint& j : frozen.joints()) {  // the balancer's closure solves itself
    EXPECT_TRUE(!j.IsMoving() || j.loop_closure >= 0) << j.name;
  }
}

TEST(FrozenJointsTest, BadKnownJointsNameTheJoint) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf",
                                 ModelLoadOptions(), &model)
                  .ok());
  KinematicModel frozen;
  for (const auto& [known, name] :
       std::vector<std::pair<KnownJoints, std::string>>{
           {{{"joint_9", 0.0}}, "joint_9"},
           {{{"piston_joint", 0.0}}, "piston_joint"},  // follows a loop closure
           {{{"joint_1", 100.0}}, "joint_1"},           // outside its limits
           {{{"joint_1", 0.1}, {"joint_1", 0.2}}, "joint_1"}}) {
    const Status status = FreezeJoints(model, known, &frozen);
    ASSERT_FALSE(status.ok()) << name;
    EXPECT_NE(status.message().find(name), std::string::npos) << status.message();
  }
}

}  // namespace
}  // namespace edgefit
