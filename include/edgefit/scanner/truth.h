// Ground truth of a virtual scan (DESIGN.md, `edgefit scan --truth=F.json`):
// what was scanned, so fits can be scored against it (paper Sec. 7.3-7.4).
//
// JSON layout (lengths [m], angles [rad], matrices 4x4 row-major nested arrays):
//   {
//     "model":   {"urdf": "robot.urdf", "attachments": ["gun.urdf@tool0", ...]},
//     "joints":  {"joint_1": 0.12, ...},        // every non-fixed joint, incl. mimic / loop
//     "T_world_base": [[...], [...], [...], [...]],
//     "base":    {"x": 0.0, "y": 0.0, "yaw": 0.0},
//     "scanners": [[[4x4 T_world_scanner]], ...],  // in scan (file) order
//     "seed": 1,
//     "settings": {"spacing": 0.0017, "noise_sigma": 0.001, "scanners": 3,
//                  "accessories": false, "random_pose": true, "full_dome": false,
//                  "max_range": 60.0, "true_edge_distance": 0.0015},
//     "counts": {"cells": N, "valid": N, "missing": N, "background": N,
//                "accessory": N, "link": N, "true_edge": N,
//                "per_link": {"link_1": N, ...}},
//     "labels_format": "<one line describing the --labels sidecar>",
//     // Only when a realistic effect is on (absent for the ideal sensor):
//     "sensor": {"name": "realistic",
//                "beam": {"sub_rays": 16, "exit_diameter": 0.0025, "divergence": 0.00019,
//                         "mixed_return": "mean", "mixed_depth": 0.003},
//                "range_noise": {"signal_model": true, ...RangeNoiseOptions},
//                "as_built": {"enabled": true, "amplitude_min": ..., "amplitude_max": ...},
//                "jackets": ["link_2", ...],          // links wearing one
//                "station_residuals": {"enabled": true, ...},
//                "scanners_written": [[[4x4]], ...],  // the poses in the scan file
//                "counts": {"mixed_pixel": N, "jacket": N}}
//   }
#ifndef EDGEFIT_SCANNER_TRUTH_H_
#define EDGEFIT_SCANNER_TRUTH_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scanner/station_residuals.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/as_built.h"

namespace edgefit {

struct TruthSettings {
  double spacing = 0.0;             // [m]
  double noise_sigma = 0.0;         // [m]
  int scanners = 0;
  bool accessories = false;
  bool random_pose = false;
  bool full_dome = false;
  double max_range = 0.0;           // [m]
  double true_edge_distance = 0.0;  // [m]
};

// The realistic effects of a scan (asset_scan.h); all off for the ideal sensor.
struct TruthSensor {
  std::string name = "ideal";
  BeamOptions beam;
  RangeNoiseOptions range_noise;
  AsBuiltOptions as_built;
  std::vector<std::string> jackets;  // links wearing a jacket
  StationResidualOptions station_residuals;
  std::vector<Pose> T_world_scanners_written;  // as in the scan file
  bool realistic() const;
};

struct LabelCounts {
  uint64_t cells = 0, valid = 0, missing = 0, background = 0, accessory = 0, link = 0;
  uint64_t true_edge = 0;  // cells with kTrueEdgeFlag
  uint64_t mixed_pixel = 0, jacket = 0;  // cells with kMixedPixelFlag, kJacketFlag
  std::vector<std::pair<std::string, uint64_t>> per_link;  // link name -> cells, links() order
};

struct Truth {
  std::string urdf;
  std::vector<std::string> attachments;                  // --attach specs as given
  std::vector<std::pair<std::string, double>> joints;    // name -> value, joints() order
  Pose T_world_base = Pose::Identity();
  double base_x = 0.0, base_y = 0.0, base_yaw = 0.0;     // [m], [m], [rad]
  std::vector<Pose> T_world_scanners;
  uint64_t seed = 0;
  TruthSettings settings;
  TruthSensor sensor;
  LabelCounts counts;
};

// Every non-fixed joint of `model` with its value in q (size joints()).
std::vector<std::pair<std::string, double>> NamedJointValues(const KinematicModel& model,
                                                            const std::vector<double>& q);
// Settings of a scan from its options.
TruthSettings MakeTruthSettings(const VirtualScanOptions& options, int scanners,
                                bool accessories, bool random_pose);
// Label statistics of a virtual scan; per_link names come from `model`,
// whose link k is labelled LinkLabel(first_link + k) (asset_scan.h, ScanCell);
// `link` counts that model's cells only.
LabelCounts CountLabels(const VirtualScan& scan, const KinematicModel& model, int first_link = 0);

// The one-line description written as "labels_format".
const char* LabelsFormatDescription();

// Writes `truth` to `path` atomically.
Status WriteTruthJson(const std::string& path, const Truth& truth);
// Reads a file written by WriteTruthJson; fails with "<path>: <problem>".
Status ReadTruthJson(const std::string& path, Truth* truth);

// The truth of a cell (edgefit scan --scene): {"assets": [{"name",
// "first_label", ...one asset's layout above...}, ...]}; every asset
// carries the scanners, settings and sensor too, and its counts' "link" and
// "per_link" are its own links'.
struct CellTruthAsset {
  std::string name;
  int first_link = 0;  // its link k is labelled LinkLabel(first_link + k)
  Truth truth;
};
Status WriteCellTruthJson(const std::string& path, const std::vector<CellTruthAsset>& assets);
// Reads a cell truth, or a one-asset truth as a cell of one (name "").
Status ReadCellTruthJson(const std::string& path, std::vector<CellTruthAsset>* assets);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_TRUTH_H_
