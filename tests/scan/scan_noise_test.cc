// The scans' own range noise (scan_noise.h): a plane with Gaussian noise
// along the rays gives back its sigma, per range bin.
#include "edgefit/scan/scan_noise.h"

#include <gtest/gtest.h>

#include <random>

namespace edgefit {
namespace {

// A camera-like grid looking at the plane z = range, noise sigma along z.
OrganizedScan NoisyPlane(double range, double sigma, uint64_t seed) {
  OrganizedScan scan(200, 300);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (int r = 0; r < 200; ++r) {
    for (int c = 0; c < 300; ++c) {
      const double x = (c - 150) * 0.004, y = (r - 100) * 0.004;
      scan.SetPoint(scan.Index(r, c), Eigen::Vector3f(x, y, range + noise(rng)), 0.0f);
    }
  }
  return scan;
}

TEST(ScanNoiseTest, APlaneGivesBackItsSigmaPerRange) {
  ScanSet scans;
  scans.scans.push_back(NoisyPlane(1.2, 0.001, 1));
  scans.scans.push_back(NoisyPlane(3.2, 0.004, 2));
  const ScanNoise noise = EstimateScanNoise(scans, ScanNoiseOptions());
  EXPECT_GT(noise.measured, 20000u);
  // The distance to the neighbours' plane has sigma sqrt(1 + 1/n) of the
  // noise's (n = 48 neighbours): within 10 %.
  EXPECT_NEAR(noise.At(1.2), 0.001, 0.0001);
  EXPECT_NEAR(noise.At(3.2), 0.004, 0.0004);
  EXPECT_NEAR(noise.At(2.1), noise.At(1.2), 1e-12);  // no measurement there: the nearest bin's
  EXPECT_TRUE(EstimateScanNoise(ScanSet(), ScanNoiseOptions()).empty());
}

}  // namespace
}  // namespace edgefit
