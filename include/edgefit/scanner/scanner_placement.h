// Placement of virtual TLS scanners around an asset (paper Sec. 7.3: "we
// nonuniformly placed virtual laser scanners to induce occlusions").
//
// Scanners stand on tripods around the asset's footprint at random,
// non-uniform azimuths; each scanner frame is level (z up, the scanner's
// rotation axis vertical) with +x pointing at the asset's box centre in the
// horizontal plane. Callers that want explicit poses skip this and pass their
// own T_world_scanner list to ScanScene.
#ifndef EDGEFIT_SCANNER_SCANNER_PLACEMENT_H_
#define EDGEFIT_SCANNER_SCANNER_PLACEMENT_H_

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"

namespace edgefit {

struct ScannerPlacementOptions {
  int count = 3;  // Number of scanners (>= 1).
  // Horizontal (Euclidean, in the floor plane) distance from the asset's
  // footprint (its box projected on the floor) to the scanner origin,
  // uniform in [min, max] [m].
  double min_distance = 2.5;
  double max_distance = 5.0;
  // Scanner origin height above the box's bottom (the floor under the
  // asset), uniform in [min, max] [m].
  double min_height = 1.2;
  double max_height = 1.8;
  // Azimuth gaps between successive scanners around the asset are
  // 2 pi / count scaled by a random factor in [1 - irregularity,
  // 1 + irregularity] (then renormalised to 2 pi): 0 = evenly spaced,
  // 0.6 = clearly non-uniform so some sides are seen by one scanner only.
  double irregularity = 0.6;
  // Random +/- yaw error of +x away from the exact direction to the box
  // centre [rad] ("roughly at the asset").
  double max_yaw_error = 0.05;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// Scanner poses T_world_scanner around `asset_box_world` (non-empty), in
// order of increasing azimuth around the box centre from a random start.
// Deterministic for a given seed. CHECK-fails on invalid options (validate
// user input with IsValid first).
std::vector<Pose> PlaceScanners(const Eigen::AlignedBox3d& asset_box_world,
                                const ScannerPlacementOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_SCANNER_PLACEMENT_H_
