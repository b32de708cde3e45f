// The negative set: scans that do not hold the model as given, fitted with
// the bundled robot and its gun at the defaults. None may end ok; the
// message must name what is wrong. (The URDF in millimetres is refused
// before the fit: bad_input_cli_test's UrdfInMillimetres.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"
#include "edgefit/scene/model_scene.h"
#include "pipeline/robot_scene.h"

namespace edgefit {
namespace {

using testing_util::GetRobotScene;
using testing_util::RobotScene;

FitResult FitTheModel(const ScanSet& scans) {
  FitResult fit;
  const Status status = Fit(GetRobotScene().model, scans, FitOptions(), nullptr, &fit);
  EXPECT_TRUE(status.ok()) << status.message();
  std::printf("  message: %s\n", fit.message.c_str());
  return fit;
}

TEST(NegativeFitTest, ScanWithoutTheRobotIsNotOk) {
  const FitResult fit = FitTheModel(GetRobotScene().empty_scans);
  EXPECT_FALSE(fit.ok);
  EXPECT_FALSE(fit.message.empty());
}

// A scan of another robot (the two-axis balancer arm of assets/models).
TEST(NegativeFitTest, ScanOfAnotherRobotIsNotOk) {
  const RobotScene& s = GetRobotScene();
  KinematicModel other;
  ASSERT_TRUE(
      LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf",
                         ModelLoadOptions(), &other)
          .ok());
  std::vector<double> q = other.ZeroJoints();
  ASSERT_TRUE(other.ResolveDependentJoints(&q).ok());
  AssetScanOptions options;
  options.accessories = true;
  options.scan.spacing = 0.004;
  options.seed = 7;
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(other, q, s.T_world_base, options, &scan, nullptr).ok());
  const FitResult fit = FitTheModel(scan.scans);
  EXPECT_FALSE(fit.ok);
  EXPECT_FALSE(fit.message.empty());
}

// The robot carries another end effector (a 0.2 m box tool, not the gun):
// the gun's links do not match, and the message says so.
TEST(NegativeFitTest, AnotherEndEffectorIsNotOk) {
  const RobotScene& s = GetRobotScene();
  const std::string assets = std::string(EDGEFIT_SOURCE_DIR) + "/assets/";
  AttachSpec tool;
  ASSERT_TRUE(ParseAttachSpec(assets + "models/simple_tool.urdf@tool0", &tool).ok());
  KinematicModel with_tool;
  ASSERT_TRUE(LoadModelWithAttachments(assets + "robot/robot.urdf", {tool}, ModelLoadOptions(),
                                       &with_tool)
                  .ok());
  std::vector<double> q = with_tool.ZeroJoints();
  ASSERT_TRUE(ParseJointAssignments(
                  "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6",
                  with_tool, &q)
                  .ok());
  ASSERT_TRUE(with_tool.ResolveDependentJoints(&q).ok());
  Scene robot;
  AddModelToScene(with_tool, with_tool.ForwardKinematics(q, s.T_world_base), &robot);
  const FitResult fit = FitTheModel(testing_util::ScanInThePlace(s, std::move(robot)).scans);
  EXPECT_FALSE(fit.ok);
  EXPECT_NE(fit.message.find("gun_"), std::string::npos) << fit.message;
}

// Clutter shaped like the base: its link alone in the place.
TEST(NegativeFitTest, TheBaseAloneIsNotOk) {
  const RobotScene& s = GetRobotScene();
  Scene all;
  AddModelToScene(s.model, s.model.ForwardKinematics(s.q, s.T_world_base), &all);
  Scene base;
  for (SceneMesh& mesh : all.meshes) {
    if (mesh.link == s.model.root_link()) base.meshes.push_back(std::move(mesh));
  }
  ASSERT_EQ(base.meshes.size(), 1u);
  const FitResult fit = FitTheModel(testing_util::ScanInThePlace(s, std::move(base)).scans);
  EXPECT_FALSE(fit.ok);
  EXPECT_FALSE(fit.message.empty());
}

// Half the robot out of every station's window (every point beyond the
// vertical plane through the base blanked): ok only if nothing is off.
TEST(NegativeFitTest, HalfOutOfTheWindowIsNotOkOrRight) {
  const RobotScene& s = GetRobotScene();
  ScanSet half = s.scans;
  const double x_cut = s.T_world_base.translation().x();
  size_t blanked = 0;
  for (OrganizedScan& scan : half.scans) {
    for (size_t cell = 0; cell < scan.size(); ++cell) {
      if (scan.IsValid(cell) && scan.PointWorld(cell).x() > x_cut) {
        scan.SetMissing(cell);
        ++blanked;
      }
    }
  }
  ASSERT_GT(blanked, s.scans.TotalValid() / 10);
  const FitResult fit = FitTheModel(half);
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(s.model, fit.q, fit.T_world_base, NamedJointValues(s.model, s.q),
                               s.T_world_base, Pose::Identity(), &errors, fit.base_symmetry)
                  .ok());
  bool off = errors.base_translation > 0.005;
  for (const JointError& e : errors.joints) off = off || e.error > (e.prismatic ? 0.005 : 0.5 * kDeg);
  std::printf("  ok %d, off %d\n", fit.ok, off);
  EXPECT_FALSE(fit.ok && off) << fit.message;
}

}  // namespace
}  // namespace edgefit
