// Test helpers for the io tests: temporary paths and scan comparison.
#ifndef EDGEFIT_TESTS_IO_IO_TEST_UTIL_H_
#define EDGEFIT_TESTS_IO_IO_TEST_UTIL_H_

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <string>

#include "edgefit/core/angles.h"
#include "edgefit/scan/organized_scan.h"
#include "scan/synthetic_scan.h"

namespace edgefit {
namespace testing {

// A fresh path under the gtest temp dir; unique per process and name.
inline std::string TempPath(const std::string& name) {
  return ::testing::TempDir() + "edgefit_io_" + std::to_string(::getpid()) + "_" + name;
}

// A small organized scan of the reader tests: 36 x 64 cells, 1 mm noise, 10%
// missing, a tilted scanner pose.
inline SyntheticScanOptions SmallScanOptions(uint32_t seed, bool color = false) {
  SyntheticScanOptions o;
  o.rows = 36;
  o.cols = 64;
  o.elevation_first = -45 * kDeg;
  o.elevation_step = 1.5 * kDeg;
  o.azimuth_first = -80 * kDeg;
  o.azimuth_step = 1.2 * kDeg;
  o.range_noise_m = 0.001;
  o.missing_fraction = 0.1;
  o.color = color;
  o.seed = seed;
  o.T_world_scanner = PoseFromXyzRpy(Eigen::Vector3d(0.5, -3.0, 1.3), Eigen::Vector3d(0.01, -0.02, 1.2));
  return o;
}

// Cell-by-cell identity: validity, points, intensities and colours exactly;
// pose to `pose_tol`; lattice tables to 1e-9 rad when both have one.
inline void ExpectSameScan(const OrganizedScan& a, const OrganizedScan& b, double pose_tol = 1e-12) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  EXPECT_EQ(a.organized(), b.organized());
  EXPECT_EQ(a.has_color(), b.has_color());
  EXPECT_TRUE(a.T_world_scanner().matrix().isApprox(b.T_world_scanner().matrix(), pose_tol))
      << a.T_world_scanner().matrix() << "\nvs\n" << b.T_world_scanner().matrix();
  size_t mismatches = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    bool same = a.IsValid(i) == b.IsValid(i);
    if (same && a.IsValid(i)) {
      same = a.point_scanner(i) == b.point_scanner(i) && a.intensity(i) == b.intensity(i);
    }
    if (same && a.has_color() && b.has_color() && a.IsValid(i)) same = a.color(i) == b.color(i);
    if (!same && ++mismatches <= 3) ADD_FAILURE() << "cell " << i << " differs";
  }
  EXPECT_EQ(mismatches, 0u);
  ASSERT_EQ(a.lattice().valid(), b.lattice().valid());
  if (a.lattice().valid()) {
    ASSERT_EQ(a.lattice().rows(), b.lattice().rows());
    ASSERT_EQ(a.lattice().cols(), b.lattice().cols());
    for (int r = 0; r < a.lattice().rows(); ++r) EXPECT_NEAR(a.lattice().elevation(r), b.lattice().elevation(r), 1e-9);
    for (int c = 0; c < a.lattice().cols(); ++c) EXPECT_NEAR(a.lattice().azimuth(c), b.lattice().azimuth(c), 1e-9);
    EXPECT_TRUE(a.lattice().R_scanner_lattice().isApprox(b.lattice().R_scanner_lattice(), 1e-9));
  }
}

}  // namespace testing
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_IO_IO_TEST_UTIL_H_
