// The scene the end-to-end micro-benchmarks share (BENCHMARK.md): the bundled
// robot (assets/robot/robot.urdf, posture "home" of postures.json without the
// gun's joint, since the gun is a separate URDF) on a floor, scanned from 3
// placed scanners with 1 mm noise, the spacing tuned so that the scans hold
// about `target_valid` points (1.93 mm for 5 M).
#ifndef EDGEFIT_BENCHMARKS_BUNDLED_ROBOT_SCAN_H_
#define EDGEFIT_BENCHMARKS_BUNDLED_ROBOT_SCAN_H_

#include <glog/logging.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/model_scene.h"

namespace edgefit {

struct BundledRobotScan {
  KinematicModel model;
  std::vector<double> q;
  ScanSet scans;
  double spacing = 0.0;  // [m]
};

inline BundledRobotScan ScanBundledRobot(double target_valid = 5.0e6) {
  BundledRobotScan out;
  CHECK(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf", {},
                           &out.model)
            .ok());
  out.q = out.model.ZeroJoints();
  CHECK(ParseJointAssignments("joint_1=0,joint_2=0,joint_3=-0.45,joint_4=0,joint_5=1.55,joint_6=0",
                              out.model, &out.q)
            .ok());
  CHECK(out.model.ResolveDependentJoints(&out.q).ok());
  Scene scene;
  SceneMesh floor;
  floor.mesh_world.vertices = {{-30, -30, 0}, {30, -30, 0}, {30, 30, 0}, {-30, 30, 0}};
  floor.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  floor.kind = "floor";
  scene.meshes.push_back(floor);
  AddModelToScene(out.model, out.model.ForwardKinematics(out.q), &scene);
  ScannerPlacementOptions placement;
  placement.count = 3;
  const std::vector<Pose> poses = PlaceScanners(out.model.BoundingBox(out.q), placement);
  VirtualScanOptions options;
  std::unique_ptr<VirtualScanner> scanner;
  CHECK(VirtualScanner::Create(scene, options, &scanner).ok());
  VirtualScan scan;
  for (int i = 0; i < 6; ++i) {  // the valid count grows with 1 / spacing^2
    CHECK(scanner->Scan(poses, options, &scan).ok());
    const double scale = std::sqrt(static_cast<double>(scan.scans.TotalValid()) / target_valid);
    if (std::abs(scale - 1.0) < 0.02) break;
    options.spacing *= scale;
  }
  out.spacing = options.spacing;
  out.scans = std::move(scan.scans);
  return out;
}

}  // namespace edgefit

#endif  // EDGEFIT_BENCHMARKS_BUNDLED_ROBOT_SCAN_H_
