// Test-only virtual TLS: ray-casts an analytic scene (floor plane, boxes,
// vertical cylinders, optional enclosing room) into an organized scan whose
// angular lattice is known exactly. Seeded range noise and dropouts.
#ifndef EDGEFIT_TESTS_SCAN_SYNTHETIC_SCAN_H_
#define EDGEFIT_TESTS_SCAN_SYNTHETIC_SCAN_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/scan/scan_lattice.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace testing {

struct SyntheticScene {
  struct Box {  // axis-aligned, world frame [m]
    Eigen::Vector3d min, max;
  };
  struct Cylinder {  // vertical, world frame [m]
    Eigen::Vector2d center;
    double radius, z_min, z_max;
  };
  bool has_floor = true;  // plane z = 0
  std::vector<Box> boxes;
  std::vector<Cylinder> cylinders;
  // Inside-out box around everything so that every ray returns.
  bool has_room = false;
  Box room{Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(10, 10, 6)};
  double max_range = 60.0;  // [m] beyond: no return
};

struct SyntheticScanOptions {
  int rows = 90;
  int cols = 180;
  double elevation_first = -1.0;  // [rad] elevation of row 0
  double elevation_step = 0.02;   // [rad] signed, per row
  double azimuth_first = -1.5;    // [rad] azimuth of column 0
  double azimuth_step = 0.015;    // [rad] signed, per column
  Eigen::Matrix3d R_scanner_lattice = Eigen::Matrix3d::Identity();  // tilt
  Pose T_world_scanner = Pose::Identity();
  double range_noise_m = 0.0;     // [m] Gaussian sigma along the ray
  double missing_fraction = 0.0;  // random dropouts
  std::vector<int> missing_rows, missing_cols;
  bool color = false;
  uint32_t seed = 1;
};

// Floor, one box and one cylinder around the origin.
SyntheticScene DefaultScene();
// DefaultScene inside a room: every ray hits.
SyntheticScene RoomScene();

// Ray-casts the scene; `truth` (optional) receives the exact lattice.
OrganizedScan MakeSyntheticScan(const SyntheticScene& scene,
                                const SyntheticScanOptions& options,
                                ScanLattice* truth = nullptr);

// The bundled sample (assets/samples/two_scans.ptx): DefaultScene seen by two
// scanners at known poses, full 360 degree scans, 1 mm noise, RGB off.
ScanSet MakeSampleScanSet();

}  // namespace testing
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SCAN_SYNTHETIC_SCAN_H_
