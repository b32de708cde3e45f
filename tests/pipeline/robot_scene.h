// The virtual scene of the robot pipeline's tests: the bundled robot with
// its weld gun and accessories (harnesses, clamps) in one posture, a floor
// and clutter, 3 scanners, 1 mm noise. At 4 mm spacing (about 1.9 M points,
// GetRobotScene, built once per test binary) for the end-to-end tests; at
// 10 mm for their small-scene twins (small_scene_fit_test).
#ifndef EDGEFIT_TESTS_PIPELINE_ROBOT_SCENE_H_
#define EDGEFIT_TESTS_PIPELINE_ROBOT_SCENE_H_

#include <glog/logging.h>

#include <cmath>
#include <utility>
#include <vector>

#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/accessories.h"
#include "edgefit/scene/environment.h"
#include "edgefit/scene/model_scene.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace testing_util {

struct RobotScene {
  KinematicModel model;
  std::vector<double> q;
  Pose T_world_base = Pose::Identity();
  std::vector<Pose> scanners;                 // T_world_scanner of the 3 stations
  ScanSet scans;                              // robot, gun, accessories, floor, clutter
  std::vector<std::vector<uint16_t>> labels;  // of scans, per cell (scene.h)
  ScanSet empty_scans;  // the same place without the robot and its accessories
  double spacing = 0.004;  // [m]
};

// `parts` (equipment in the world frame, possibly none) in the scene's
// place: its floor and clutter added, scanned from its stations.
inline VirtualScan ScanInThePlace(const RobotScene& s, Scene parts) {
  const Eigen::AlignedBox3d box = s.model.BoundingBox(s.q, s.T_world_base);
  EnvironmentOptions environment;
  environment.seed = 3;
  AddEnvironment(box, environment, &parts);
  VirtualScanOptions options;
  options.spacing = s.spacing;
  options.seed = 11;
  options.asset_box_world = box;
  VirtualScan scan;
  CHECK(ScanScene(parts, s.scanners, options, &scan).ok());
  return scan;
}

// The scene at `spacing` [m]; the caller owns it.
inline RobotScene* MakeRobotScene(double spacing) {
  auto* out = new RobotScene;
  out->spacing = spacing;
  LoadBundledRobotWithGun(
      "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
      &out->model, &out->q);
  out->T_world_base = PoseFromXyzRpy({0.5, -0.2, 0.0}, {0.0, 0.0, 15.0 * M_PI / 180.0});
  ScannerPlacementOptions placement;
  placement.seed = 5;
  out->scanners = PlaceScanners(out->model.BoundingBox(out->q, out->T_world_base), placement);
  const std::vector<Pose> T_world_link = out->model.ForwardKinematics(out->q, out->T_world_base);
  Scene robot;
  AddModelToScene(out->model, T_world_link, &robot);
  AccessoryOptions accessories;
  accessories.seed = 2;
  AddAccessories(out->model, out->q, T_world_link, accessories, &robot);
  VirtualScan scan = ScanInThePlace(*out, std::move(robot));
  out->labels = std::move(scan.labels);
  out->scans = std::move(scan.scans);
  out->empty_scans = ScanInThePlace(*out, Scene()).scans;
  return out;
}

inline const RobotScene& GetRobotScene() {
  static RobotScene* scene = MakeRobotScene(0.004);
  return *scene;
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_PIPELINE_ROBOT_SCENE_H_
