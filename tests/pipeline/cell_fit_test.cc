// The cell fit (pipeline/cell_fit.h) on a small virtual cell: two bundled
// robots with their guns side by side and a balancer arm that is not looked
// for, 3 scanners, 4 mm. Both robots found without hints, each within the
// pipeline test's accuracy of a different one, none invented, their points
// gone from the background and the balancer's kept.
#include "edgefit/pipeline/cell_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"
#include "edgefit/scene/scene.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

constexpr double kDeg = M_PI / 180.0;

#if defined(__SANITIZE_ADDRESS__)
#define SKIP_UNDER_ASAN() GTEST_SKIP() << "three whole fits: release suite only"
#else
#define SKIP_UNDER_ASAN() (void)0
#endif

TEST(CellFitTest, FindsBothRobotsAndLeavesTheOtherMachine) {
  SKIP_UNDER_ASAN();
  KinematicModel robot, balancer;
  std::vector<double> q_left, q_right;
  testing_util::LoadBundledRobotWithGun("joint_1=0.4,joint_2=0.5,joint_3=-0.2,joint_5=0.7,gun_joint=0.05", &robot,
                                        &q_left);
  testing_util::LoadBundledRobotWithGun("joint_1=-0.5,joint_2=0.3,joint_4=0.6,joint_5=0.5,gun_joint=0.1", &robot,
                                        &q_right);
  ASSERT_TRUE(LoadModelWithAttachments(std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf", {},
                                       ModelLoadOptions(), &balancer)
                  .ok());
  std::vector<double> q_balancer = balancer.ZeroJoints();
  ASSERT_TRUE(balancer.ResolveDependentJoints(&q_balancer).ok());
  const Pose T_left = PoseFromXyYaw(-1.4, -1.0, M_PI / 2), T_right = PoseFromXyYaw(1.4, -1.0, M_PI / 2);
  const std::vector<CellAsset> assets = {
      {&robot, q_left, T_left}, {&robot, q_right, T_right}, {&balancer, q_balancer, PoseFromXyYaw(0.0, 2.0, M_PI)}};
  AssetScanOptions scan_options;
  scan_options.scan.spacing = 0.004;
  scan_options.seed = 5;
  VirtualScan cell;
  std::vector<int> first_link;
  ASSERT_TRUE(ScanCell(assets, scan_options, &cell, nullptr, &first_link).ok());

  CellModel model;
  model.name = "robot";
  model.model = &robot;
  model.options = FitOptionsFor(AssetKind::kArticulated);
  ScanSet scans = cell.scans;
  CellResult result;
  ASSERT_TRUE(FitCell({model}, CellOptions(), nullptr, &scans, &result).ok());

  ASSERT_EQ(result.instances.size(), 2u);
  ASSERT_EQ(result.models.size(), 1u);
  EXPECT_FALSE(result.models[0].stopped.empty());  // the third search said why it found nothing
  EXPECT_TRUE(result.models[0].rejected);
  std::vector<bool> matched(2, false);
  for (const CellInstance& instance : result.instances) {
    const int a = (instance.fit.T_world_base.translation() - T_left.translation()).norm() < 0.1 ? 0 : 1;
    ASSERT_LT((instance.fit.T_world_base.translation() - assets[a].T_world_base.translation()).norm(), 0.01);
    EXPECT_FALSE(matched[a]) << "asset " << a << " found twice";
    matched[a] = true;
    FitErrors errors;
    ASSERT_TRUE(CompareWithTruth(robot, instance.fit.q, instance.fit.T_world_base,
                                 NamedJointValues(robot, assets[a].q), assets[a].T_world_base, Pose::Identity(),
                                 &errors)
                    .ok());
    MarkUnobservableJoints(instance.fit.bodies, &errors);
    EXPECT_LT(errors.base_translation, 0.0005) << "asset " << a;
    for (const JointError& e : errors.joints) {
      if (e.independent && !e.prismatic && !e.unobservable) {
        EXPECT_LT(std::abs(e.error), 0.05 * kDeg) << e.name;
      }
    }
  }
  // The background: the robots' link points gone, the balancer's kept.
  size_t robot_cells = 0, robot_left = 0, balancer_cells = 0, balancer_left = 0;
  const int robot_links = static_cast<int>(robot.links().size());
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    for (size_t i = 0; i < scans.scans[s].size(); ++i) {
      const uint16_t label = cell.labels[s][i];
      if (!IsLinkLabel(label)) continue;
      const bool on_robot = LinkOfLabel(label) < 2 * robot_links;
      (on_robot ? robot_cells : balancer_cells)++;
      if (scans.scans[s].IsValid(i)) (on_robot ? robot_left : balancer_left)++;
    }
  }
  EXPECT_GT(robot_cells, 10000u);
  EXPECT_LT(robot_left, robot_cells / 100);
  EXPECT_GT(balancer_cells, 1000u);
  EXPECT_GT(balancer_left, balancer_cells * 98 / 100);
  EXPECT_EQ(result.background_points, scans.TotalValid());
}

}  // namespace
}  // namespace edgefit
