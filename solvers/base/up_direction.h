// Which way is up in a scan whose frame is not levelled: a depth camera's
// frame, or one whose pose (a PCD's VIEWPOINT) is turned. The upright base
// search (Sec. 5.1.1) cuts horizontal slices, so it needs gravity; a laser
// scanner's compensator gives it, a camera's pose may not.
//
// Up is the normal of the dominant plane (a floor, or the table the robot
// stands on) among the planes within `max_tilt` of the frame's z: RANSAC
// over triples of a deterministic sample of the valid points, each plane
// scored by its points within `inlier_distance`, the best refined by a
// principal-component fit of its inliers (`refinements` times; a plane that then leaves
// the bound is a steeper one's strip: none), and turned to face the
// first scanner (a camera sees a floor's upper side). Up only guides the
// search: every pose stays in the scan file's frame.
#ifndef EDGEFIT_SOLVERS_BASE_UP_DIRECTION_H_
#define EDGEFIT_SOLVERS_BASE_UP_DIRECTION_H_

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>

#include "edgefit/core/status.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct UpOptions {
  // Planes whose normal is more than this from the frame's z are walls,
  // not floors [rad] (50 degrees: a frame turned by a few tens of degrees).
  double max_tilt = 50.0 * 3.14159265358979323846 / 180.0;
  // A point within this of a plane is on it [m] (a stereo camera's noise at
  // 3 m is about 1 to 3 cm).
  double inlier_distance = 0.02;
  // The plane must hold at least this share of the sampled points.
  double min_share = 0.05;
  size_t max_points = 30000;  // points sampled from the scans
  int iterations = 600;       // RANSAC triples
  // Least-squares refinements of the best plane on its inliers: a plane
  // that cuts a steeper surface in a strip turns toward it.
  int refinements = 10;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

struct UpEstimate {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // unit, world frame
  double tilt = 0.0;                              // angle between up and the world z [rad]
  size_t inliers = 0;                             // sampled points on the plane
  size_t sampled = 0;                             // points sampled
};

// Fails when no plane within max_tilt of z holds min_share of the points.
Status EstimateUp(const ScanSet& scans, const UpOptions& options, UpEstimate* estimate);

// The rotation about the world origin that takes `up` to the world z along
// the shortest arc (identity when they agree).
Eigen::Matrix3d LevellingRotation(const Eigen::Vector3d& up);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_UP_DIRECTION_H_
