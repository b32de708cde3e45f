// A cell scene file: the assets `edgefit scan --scene=F.json` places in one
// cell (asset_scan.h, ScanCell). Paths are relative to the file's folder.
//
//   {"assets": [
//     {"name": "robot_left", "urdf": "robot/robot.urdf",
//      "attach": "robot/weld_gun.urdf@tool0",           // optional, as --attach
//      "posture": "robot/postures.json:weld_low",        // at most one of posture,
//      "joints": "joint_1=20deg,joint_2=-0.3",           //   joints (as --joints)
//      "random_pose": true,                              //   and random_pose; else zero
//      "base": [0.5, -1.5, 15]},                         // x [m], y [m], yaw [deg]
//     ...]}
#ifndef EDGEFIT_SCANNER_CELL_SCENE_H_
#define EDGEFIT_SCANNER_CELL_SCENE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

struct CellSceneAsset {
  std::string name;
  std::string urdf;  // as resolved
  std::vector<AttachSpec> attachments;
  KinematicModel model;
  std::vector<double> q;
  double base_x = 0.0, base_y = 0.0, base_yaw = 0.0;  // [m], [m], [rad]
  Pose T_world_base = Pose::Identity();
};

// Reads the file, loads every model with its attachments and sets its
// joints; random postures draw from SplitMix64::StreamSeed(seed, 2000 + a)
// and stay above the floor (z = 0). Fails naming the file and the asset.
Status LoadCellScene(const std::string& path, uint64_t seed, std::vector<CellSceneAsset>* assets);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_CELL_SCENE_H_
