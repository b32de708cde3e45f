// Rough base registration (paper Sec. 5.1.1) on a virtual scan: a round
// base with a box on one side (four corners per section, two of them
// concave) standing on the floor, 3 scanners, 1.7 mm spacing, 1 mm noise.
// The corner-pair RANSAC and, with no usable pair, the single-corner search
// each put the base within 1.5 cm and 1.5 degrees: close
// enough for the precise ICP.
#include "solvers/base/base_rough.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "edgefit/core/angles.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/core/split_mix64.h"
#include "solvers/base/cross_sections.h"
#include "solvers/base/floor_height.h"
#include "solvers/icp_test_util.h"
#include "solvers/link_scan_test_util.h"

namespace edgefit {
namespace {

using testing_util::RotationErrorRad;
using testing_util::TranslationError;

using testing_util::RoundBaseWithBox;

const Pose kTrueBasePose = PoseFromXyzRpy({1.2, -0.4, 0.0}, {0, 0, 0.7});

struct BaseScene {
  ScanSet scans;
  double floor_z = 0.0;
};

const BaseScene& GetBaseScene() {
  static BaseScene* scene = [] {
    auto* out = new BaseScene;
    VirtualScan scan = testing_util::ScanLinkOnFloor(RoundBaseWithBox(), kTrueBasePose, {}, 5);
    out->scans = std::move(scan.scans);
    CHECK(
        EstimateFloorHeight(out->scans, Eigen::AlignedBox3d(), FloorOptions(), &out->floor_z).ok());
    return out;
  }();
  return *scene;
}

void ExpectNearTruth(const BaseRoughOptions& options) {
  const BaseScene& s = GetBaseScene();
  BaseRoughResult result;
  const Status status = FitBaseRough(s.scans, s.floor_z, RoundBaseWithBox(), options, &result);
  ASSERT_TRUE(status.ok()) << status.message();
  const double t = TranslationError(result.T_world_base, kTrueBasePose);
  const double r = RotationErrorRad(result.T_world_base, kTrueBasePose);
  std::printf("  %d scan, %d model corners, %d hypotheses, inlier share %.3f: %.2f mm, %.3f deg\n",
              result.scan_corners, result.model_corners, result.hypotheses, result.inlier_share,
              1e3 * t, r / kDeg);
  EXPECT_NEAR(result.floor_z, 0.0, 1e-3);
  EXPECT_LT(t, 0.015);
  EXPECT_LT(r, 1.5 * kDeg);
  EXPECT_GT(result.inlier_share, 0.5);
}

TEST(BaseRoughTest, CornerPairsFindTheBase) { ExpectNearTruth(BaseRoughOptions()); }

// No corner pair is long enough to draw: only the single-corner search
// (each scan corner onto each model corner, yaw on a 1 degree grid) runs.
TEST(BaseRoughTest, SingleCornerSearchFindsTheBaseWithoutPairs) {
  BaseRoughOptions options;
  options.min_pair_length = 10.0;
  ExpectNearTruth(options);
}

TEST(BaseRoughTest, BadSingleCornerOptionsAreRejected) {
  BaseRoughOptions options;
  options.single_corner_yaw_step = 0.0;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("single-corner"), std::string::npos) << error;
}

// A square section 0.6 m wide, a point every 2 mm, scattered across its
// sides by 4 mm (a depth camera's few millimetres): at the laser scan's
// distances its straight runs read as corners and the four real ones are
// lost among them; scaled to the noise, the four corners are found.
TEST(BaseRoughTest, CornersScaledToTheNoiseFindASquaresCorners) {
  constexpr double kHalf = 0.3, kSigma = 0.004;
  SplitMix64 rng(7);
  auto gauss = [&rng] {  // Box-Muller
    const double u = 1.0 - rng.Uniform();  // (0, 1]
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * rng.Uniform());
  };
  Section section;
  const Eigen::Vector2d corners[4] = {{-kHalf, -kHalf}, {kHalf, -kHalf}, {kHalf, kHalf}, {-kHalf, kHalf}};
  for (int side = 0; side < 4; ++side) {
    const Eigen::Vector2d a = corners[side], b = corners[(side + 1) % 4];
    const Eigen::Vector2d across(-(b - a).y() / (2 * kHalf), (b - a).x() / (2 * kHalf));
    for (double s = 0.0; s < 2 * kHalf; s += 0.002) {
      section.points.push_back(a + (b - a) * (s / (2 * kHalf)) + kSigma * gauss() * across);
    }
  }
  auto found = [&](const BaseRoughOptions& options) {
    int near = 0;
    const std::vector<int> found = SectionCorners(section, options.corners);
    for (const int i : found) {
      for (const Eigen::Vector2d& c : corners) near += (section.points[static_cast<size_t>(i)] - c).norm() < 0.03;
    }
    std::printf("  radius %.0f mm: %zu corners, %d at the square's\n", 1e3 * options.corners.radius,
                found.size(), near);
    return std::make_pair(found.size(), near);
  };
  const auto laser = found(BaseRoughOptions());
  EXPECT_FALSE(laser.first == 4 && laser.second == 4);
  const auto scaled = found(BaseRoughOptions().ScaledToNoise(kSigma));
  EXPECT_EQ(scaled.first, 4u);
  EXPECT_EQ(scaled.second, 4);
}

TEST(BaseRoughTest, ScalingToNoiseKeepsLaserScansAndIsBounded) {
  const BaseRoughOptions options;
  EXPECT_EQ(options.ScaledToNoise(0.0008).inlier_distance, options.inlier_distance);
  EXPECT_EQ(options.ScaledToNoise(NAN).corners.radius, options.corners.radius);
  const BaseRoughOptions wide = options.ScaledToNoise(1.0);
  EXPECT_DOUBLE_EQ(wide.corners.radius, options.max_noise_scale * options.corners.radius);
  EXPECT_DOUBLE_EQ(wide.pair_tolerance, options.max_noise_scale * options.pair_tolerance);
  EXPECT_EQ(wide.max_edge, options.max_edge);
}

TEST(BaseRoughTest, NoiseLevelsFollowTheRangesOfADepthCamera) {
  const BaseRoughOptions options;
  ScanNoise laser;  // about half a millimetre at every range: k = 1 throughout
  laser.median_sigma = 0.0005;
  laser.sigma = {NAN, 0.0004, 0.0005, 0.0006, 0.0007};
  EXPECT_EQ(options.NoiseLevels(laser), std::vector<double>({0.0005}));
  ScanNoise camera;  // the floor before the camera holds the median
  camera.median_sigma = 0.0009;
  camera.sigma = {0.0004, 0.001, 0.002, 0.0025, NAN, 0.0035, 0.0045, 0.02};
  // The median (k 1), then 2 mm (k 2), 3.5 mm (k 3.5) and 20 mm (k at its
  // bound, 6); 2.5 and 4.5 mm are within 1.5 times a kept k.
  EXPECT_EQ(options.NoiseLevels(camera), std::vector<double>({0.0009, 0.002, 0.0035, 0.02}));
  ScanNoise none;  // no measurement: the median's k = 1 alone
  EXPECT_EQ(options.NoiseLevels(none), std::vector<double>({0.0}));
}

}  // namespace
}  // namespace edgefit
