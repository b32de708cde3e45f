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

}  // namespace
}  // namespace edgefit
