// The cell fit (pipeline/cell_fit.h) on a small virtual cell: two bundled
// robots with their guns and accessories side by side and a balancer arm
// that is not looked for, 3 scanners, 4 mm. Both robots found without
// hints, each within the pipeline test's accuracy of a different one, none
// invented, their points and their accessories' gone from the background,
// the balancer's kept.
#include "edgefit/pipeline/cell_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"
#include "edgefit/scene/scene.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

TEST(CellFitTest, FindsBothRobotsAndLeavesTheOtherMachine) {
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
  scan_options.accessories = true;
  // With seed 5 the right robot's square base came out turned 180 deg with
  // joint_1 making up for it, said ok, before the base's symmetry was
  // reported by its convention (FitResult::base_symmetry).
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
                                 &errors, instance.fit.base_symmetry)
                    .ok());
    MarkUnobservableJoints(instance.fit.bodies, &errors);
    EXPECT_LT(errors.base_translation, 0.0005) << "asset " << a;
    EXPECT_LT(errors.base_rotation, 0.05 * kDeg) << "asset " << a;
    for (const JointError& e : errors.joints) {
      if (e.independent && !e.prismatic && !e.unobservable) {
        EXPECT_LT(std::abs(e.error), 0.05 * kDeg)
            << e.name << " of asset " << a << "; fit ok " << instance.fit.ok << ": " << instance.fit.message;
      }
    }
  }
  // The background: the robots' link and accessory points gone, the
  // balancer's kept (accessories share one label: told by the nearest base).
  size_t robot_cells = 0, robot_left = 0, balancer_cells = 0, balancer_left = 0;
  size_t robot_accessory = 0, robot_accessory_left = 0, balancer_accessory = 0, balancer_accessory_left = 0;
  const int robot_links = static_cast<int>(robot.links().size());
  const Eigen::Vector2d balancer_xy = assets[2].T_world_base.translation().head<2>();
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    for (size_t i = 0; i < scans.scans[s].size(); ++i) {
      const uint16_t label = cell.labels[s][i];
      const bool left = scans.scans[s].IsValid(i);
      if (IsLinkLabel(label)) {
        const bool on_robot = LinkOfLabel(label) < 2 * robot_links;
        (on_robot ? robot_cells : balancer_cells)++;
        if (left) (on_robot ? robot_left : balancer_left)++;
      } else if ((label & kLabelMask) == kLabelAccessory) {
        const bool near_balancer =
            (cell.scans.scans[s].PointWorld(i).head<2>() - balancer_xy).norm() < 1.0;
        (near_balancer ? balancer_accessory : robot_accessory)++;
        if (left) (near_balancer ? balancer_accessory_left : robot_accessory_left)++;
      }
    }
  }
  EXPECT_GT(robot_cells, 10000u);
  EXPECT_LT(robot_left, robot_cells / 100);
  EXPECT_GT(balancer_cells, 1000u);
  EXPECT_GT(balancer_left, balancer_cells * 98 / 100);
  EXPECT_GT(robot_accessory, 5000u);
  EXPECT_LT(robot_accessory_left, robot_accessory / 5) << "of " << robot_accessory;  // 11% measured
  EXPECT_GT(balancer_accessory_left, balancer_accessory * 9 / 10) << "of " << balancer_accessory;
  EXPECT_EQ(result.background_points, scans.TotalValid());
}

// Robots are looked for before conveyance systems, whatever the order the
// models are listed in; each group keeps its own order.
TEST(CellFitTest, RobotsAreLookedForBeforeConveyors) {
  std::vector<CellModel> models(4);
  models[0].options = FitOptionsFor(AssetKind::kConveyance);
  models[1].options = FitOptionsFor(AssetKind::kArticulated);
  models[2].options = FitOptionsFor(AssetKind::kConveyance);
  models[3].options = FitOptionsFor(AssetKind::kArticulated);
  EXPECT_EQ(SearchOrder(models), (std::vector<size_t>{1, 3, 0, 2}));
}

}  // namespace
}  // namespace edgefit
