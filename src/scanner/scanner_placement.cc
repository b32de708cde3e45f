#include "edgefit/scanner/scanner_placement.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "counter_rng.h"
#include "edgefit/core/angles.h"

namespace edgefit {
namespace {

// Euclidean distance of the floor point (x, y), relative to the box centre,
// from the box's footprint (an axis-aligned rectangle of half sizes hx, hy).
double FootprintDistance(double hx, double hy, double x, double y) {
  return std::hypot(std::max(std::abs(x) - hx, 0.0), std::max(std::abs(y) - hy, 0.0));
}

// Radius r along the unit direction (c, s) from the box centre at which the
// footprint distance equals `distance`. The footprint distance grows
// monotonically with r (the rectangle is convex and contains the centre), so
// bisection converges; 60 halvings reach double precision.
double RadiusAtFootprintDistance(double hx, double hy, double c, double s, double distance) {
  double lo = 0.0, hi = std::hypot(hx, hy) + distance + 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (FootprintDistance(hx, hy, mid * c, mid * s) < distance ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

bool ScannerPlacementOptions::IsValid(std::string* error) const {
  auto fail = [error](const char* message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (count < 1) return fail("scanner count must be >= 1");
  if (!(min_distance >= 0.0) || !(max_distance >= min_distance)) {
    return fail("scanner distances must satisfy 0 <= min_distance <= max_distance");
  }
  if (!(max_height >= min_height)) return fail("scanner heights must satisfy min <= max");
  if (!(irregularity >= 0.0 && irregularity < 1.0)) {
    return fail("scanner azimuth irregularity must be in [0, 1)");
  }
  if (!(max_yaw_error >= 0.0)) return fail("scanner yaw error must be >= 0");
  return true;
}

std::vector<Pose> PlaceScanners(const Eigen::AlignedBox3d& asset_box_world,
                                const ScannerPlacementOptions& options) {
  std::string error;
  CHECK(options.IsValid(&error)) << error;
  CHECK(!asset_box_world.isEmpty()) << "PlaceScanners needs a non-empty asset box";
  SplitMix64 rng(options.seed);

  // Random azimuth gaps, renormalised to close the circle.
  const int n = options.count;
  std::vector<double> gaps(n);
  double gap_sum = 0.0;
  for (double& gap : gaps) {
    gap = rng.Uniform(1.0 - options.irregularity, 1.0 + options.irregularity);
    gap_sum += gap;
  }
  const Eigen::Vector3d centre = asset_box_world.center();
  const Eigen::Vector3d half = 0.5 * asset_box_world.sizes();
  double azimuth = rng.Uniform(-kPi, kPi);

  std::vector<Pose> poses;
  poses.reserve(n);
  for (int k = 0; k < n; ++k) {
    const double c = std::cos(azimuth), s = std::sin(azimuth);
    const double distance = rng.Uniform(options.min_distance, options.max_distance);
    const double height = rng.Uniform(options.min_height, options.max_height);
    const double yaw_error = rng.Uniform(-options.max_yaw_error, options.max_yaw_error);
    const double radius = RadiusAtFootprintDistance(half.x(), half.y(), c, s, distance);
    const Eigen::Vector3d position(centre.x() + radius * c, centre.y() + radius * s,
                                   asset_box_world.min().z() + height);
    // +x looks back at the centre: yaw = azimuth + pi.
    const double yaw = azimuth + kPi + yaw_error;
    Pose T_world_scanner = Pose::Identity();
    T_world_scanner.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T_world_scanner.translation() = position;
    poses.push_back(T_world_scanner);
    azimuth += 2.0 * kPi * gaps[k] / gap_sum;
  }
  return poses;
}

}  // namespace edgefit
