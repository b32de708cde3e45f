#include "edgefit/model/calibrated_urdf.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "edgefit/model/urdf_loader.h"
#include "model/calibrated_urdf_check.h"

namespace edgefit {
namespace {

const std::string kRobot = EDGEFIT_SOURCE_DIR "/assets/robot/";

// The bundled robot with its weld gun on tool0.
bool LoadRobotWithGun(std::vector<AttachSpec>* specs, KinematicModel* model) {
  return ParseAttachSpecList(kRobot + "weld_gun.urdf@tool0", specs).ok() &&
         LoadModelWithAttachments(kRobot + "robot.urdf", *specs, ModelLoadOptions(), model).ok();
}

// The calibrated URDF of the bundled robot with its gun, written to another
// directory and loaded back: every link of the fitted model (gun included)
// with its mesh, and each one where the fit put it.
TEST(CalibratedUrdfTest, LoadsBackWithTheEndEffectorAtTheFittedPose) {
  std::vector<AttachSpec> specs;
  KinematicModel model;
  ASSERT_TRUE(LoadRobotWithGun(&specs, &model));
  std::vector<double> q = model.ZeroJoints();
  const char* names[] = {"joint_1", "joint_2", "joint_5", "gun_joint"};
  const double values[] = {0.4, -0.3, 1.1, 0.05};
  for (int k = 0; k < 4; ++k) q[static_cast<size_t>(model.JointIndex(names[k]))] = values[k];
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  const Pose T_world_base = PoseFromXyzRpy({1.5, -0.25, 0.002}, {0.001, -0.002, 0.7});

  const std::string text = testing_util::ExpectCalibratedUrdfLoadsBack(
      kRobot + "robot.urdf", specs, model, q, T_world_base, "calibrated_urdf_test");
  EXPECT_NE(text.find("gun_joint=0.05"), std::string::npos);
}

TEST(CalibratedUrdfTest, RefusesPrefixedAttachmentsAndWrongJointCounts) {
  std::vector<AttachSpec> specs;
  KinematicModel model;
  ASSERT_TRUE(LoadRobotWithGun(&specs, &model));
  std::string text;
  Status status = CalibratedUrdf(kRobot + "robot.urdf", specs, model, Pose::Identity(), {0.0},
                                 ModelLoadOptions(), &text);
  EXPECT_NE(status.message().find("joint values"), std::string::npos) << status.message();
  specs[0].prefix = "a_";
  status = CalibratedUrdf(kRobot + "robot.urdf", specs, model, Pose::Identity(), model.ZeroJoints(),
                          ModelLoadOptions(), &text);
  EXPECT_NE(status.message().find("prefix"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace edgefit
