// A robot on a linear track (../shared/robots: KUKA KR 150-2 on its 8.2 m
// rail, the X16005 weld gun on its flange), fitted as an articulated robot:
// the rail is its base, the carriage a prismatic joint of the chain. The
// case is random_1 of the accuracy benchmark (benchmarks/robot_accuracy,
// seed 1, no accessories), whose rail the cross sections placed 0.6 m off
// along its length before candidates slid along it
// (BaseHypothesesOptions::slide_elongation). Skips without ../shared/robots.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "edgefit/bench/bench_case.h"
#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/scanner/truth.h"

namespace edgefit {
namespace {

TEST(LinearTrackFitTest, TheRailSlidesToItsPlace) {
  const std::string robots = std::string(EDGEFIT_SHARED_DIR) + "/robots/";
  const std::string urdf = robots + "kuka_kr150_2_on_linear_axis/kuka_kr150_2_on_linear_axis.urdf";
  const std::string gun = robots + "weld_gun_x16005_botrail/weld_gun_x16005_botrail.urdf";
  if (!std::filesystem::exists(urdf) || !std::filesystem::exists(gun)) {
    GTEST_SKIP() << "../shared/robots absent";
  }
  AttachSpec spec;
  ASSERT_TRUE(ParseAttachSpec(gun + "@robot_tool0", &spec).ok());
  KinematicModel model;
  ASSERT_TRUE(LoadModelWithAttachments(urdf, {spec}, ModelLoadOptions(), &model).ok());
  AssetKind kind = AssetKind::kConveyance;
  ASSERT_TRUE(ChooseAssetKind("auto", model, &kind).ok());
  EXPECT_EQ(kind, AssetKind::kArticulated);  // revolute joints: not a conveyor

  const BenchCase c = MakeBenchCase("random_1", 1, 1001, 1.0);  // as robot_accuracy
  const uint64_t seed = c.seed;
  const Pose& T_world_base = c.T_world_base;
  std::vector<double> q;
  ASSERT_TRUE(RandomJointValuesAboveFloor(model, T_world_base, 0.0, Mix64(seed), &q));
  AssetScanOptions scan_options;
  scan_options.scan.spacing = 0.003;
  scan_options.scan.noise_sigma = 0.001;
  scan_options.seed = seed;
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(model, q, T_world_base, scan_options, &scan, nullptr).ok());

  FitResult fit;
  ASSERT_TRUE(Fit(model, scan.scans, FitOptionsFor(kind), nullptr, &fit).ok());
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(model, fit.q, fit.T_world_base, NamedJointValues(model, q),
                               T_world_base, Pose::Identity(), &errors)
                  .ok());
  std::printf("  %zu points; base %.3f mm %.4f deg; %.1f s\n", scan.scans.TotalValid(),
              1e3 * errors.base_translation, errors.base_rotation / kDeg, fit.timings.total);
  EXPECT_LT(errors.base_translation, 0.0005);
  EXPECT_LT(errors.base_rotation, 0.01 * kDeg);
  for (const JointError& e : errors.joints) {
    if (!e.independent) continue;
    std::printf("  %-28s %.4f %s\n", e.name.c_str(), e.prismatic ? 1e3 * e.error : e.error / kDeg,
                e.prismatic ? "mm" : "deg");
    EXPECT_LT(e.error, e.prismatic ? 0.001 : 0.1 * kDeg) << e.name;
  }
  EXPECT_TRUE(fit.ok) << fit.message;
}

}  // namespace
}  // namespace edgefit
