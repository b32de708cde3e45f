// The conveyance pipeline end to end (paper Sec. 6) on a small virtual scan
// of the bundled conveyor: accessories, clutter, 3 scanners, 5 mm spacing,
// 1 mm noise, the base turned by 160 degrees and the clamps opened unequally
// (the clamp tips are not mirrored about the centre axis). The base's rough
// pose must come from the arm tips (Sec. 6.1), every prismatic joint within
// a fraction of a millimetre; a frame turned half a turn must be told by its
// links; --kind=auto must tell conveyors from robots.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgefit/bench/bench_case.h"
#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/scanner/truth.h"

namespace edgefit {
namespace {

struct ConveyorScene {
  KinematicModel model;
  std::vector<double> q;
  Pose T_world_base = Pose::Identity();
  ScanSet scans;
};

const ConveyorScene& GetScene() {
  static ConveyorScene* scene = [] {
    auto* out = new ConveyorScene;
    CHECK(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/conveyor/conveyor.urdf",
                             ModelLoadOptions(), &out->model)
              .ok());
    out->q = out->model.ZeroJoints();
    CHECK(ParseJointAssignments("carriage_1_joint=-0.35,lifter_1_joint=0.13,"
                                "carriage_2_joint=0.62,lifter_2_joint=0.04,"
                                "clamp_2_left_joint=0.015,clamp_2_right_joint=0.1",
                                out->model, &out->q)
              .ok());
    out->T_world_base = PoseFromXyzRpy({0.7, -0.4, 0.0}, {0.0, 0.0, 160.0 * kDeg});
    AssetScanOptions options;
    options.accessories = true;
    options.scan.spacing = 0.005;
    options.scan.noise_sigma = 0.001;
    options.seed = 7;
    VirtualScan scan;
    CHECK(ScanAsset(out->model, out->q, out->T_world_base, options, &scan, nullptr).ok());
    out->scans = std::move(scan.scans);
    return out;
  }();
  return *scene;
}

TEST(ConveyanceFitTest, RecoversBaseAndPrismaticJointsFromTheArmTips) {
  const ConveyorScene& s = GetScene();
  AssetKind kind = AssetKind::kArticulated;
  ASSERT_TRUE(ChooseAssetKind("auto", s.model, &kind).ok());
  ASSERT_EQ(kind, AssetKind::kConveyance);
  FitResult fit;
  const Status status = Fit(s.model, s.scans, FitOptionsFor(kind), nullptr, &fit);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(fit.base_rough_method, BaseOptions::Method::kArmTips);
  // Four arm tips: lifter_1's pair is mirrored about the centre axis, the
  // clamps' pair (opened 15 and 100 mm) about a line 4.25 cm beside it.
  EXPECT_GE(fit.arm_tips.scan_tips.size(), 4u);
  EXPECT_EQ(fit.arm_tips.model_tips.size(), 4u);
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(s.model, fit.q, fit.T_world_base, NamedJointValues(s.model, s.q),
                               s.T_world_base, Pose::Identity(), &errors)
                  .ok());
  // The rough pose is within the precise ICP's first gate (5 cm).
  const Pose T_rough_truth = fit.base_rough.T_world_base.inverse() * s.T_world_base;
  std::printf("  %zu points; rough base %.1f mm; base %.3f mm %.4f deg; %.2f s\n",
              s.scans.TotalValid(), 1e3 * T_rough_truth.translation().norm(),
              errors.base_translation * 1e3, errors.base_rotation / kDeg, fit.timings.total);
  EXPECT_LT(T_rough_truth.translation().norm(), 0.03);
  EXPECT_LT(errors.base_translation, 0.0005);
  EXPECT_LT(errors.base_rotation, 0.02 * kDeg);
  for (const JointError& e : errors.joints) {
    std::printf("  %-22s error %.3f mm\n", e.name.c_str(), 1e3 * e.error);
    EXPECT_LT(e.error, 0.001) << e.name;
  }
  EXPECT_TRUE(fit.ok) << fit.message;
}

// The frame looks nearly the same turned half a turn (only the drive unit
// at its +x end tells): random_2 of the accuracy benchmark
// (benchmarks/robot_accuracy, seed 1, 3 mm spacing, accessories), whose
// turned rough pose scores better alone, the base's own Eq. 9 loss. Fitted
// through the whole chain both ways round, the model picks the right one.
TEST(ConveyanceFitTest, AFrameTurnedHalfATurnIsToldByItsLinks) {
  const ConveyorScene& s = GetScene();
  const BenchCase c = MakeBenchCase("random_2", 1, 1002, 1.0);  // as robot_accuracy
  const uint64_t seed = c.seed;
  const Pose& T_world_base = c.T_world_base;
  std::vector<double> q;
  ASSERT_TRUE(RandomJointValuesAboveFloor(s.model, T_world_base, 0.0, Mix64(seed), &q));
  AssetScanOptions scan_options;
  scan_options.accessories = true;
  scan_options.scan.spacing = 0.003;
  scan_options.scan.noise_sigma = 0.001;
  scan_options.seed = seed;
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(s.model, q, T_world_base, scan_options, &scan, nullptr).ok());
  for (const int alternatives : {0, 1}) {
    FitOptions options = FitOptionsFor(AssetKind::kConveyance);
    options.base.hypotheses.alternatives = alternatives;
    // The paper's height map (each cell's highest point): the corroborated
    // one finds the right pose first on this scene.
    options.base.arm_tips.scan_support.points = 1;
    options.base.arm_tips.scan_support.cell_share = 0.0;
    FitResult fit;
    ASSERT_TRUE(Fit(s.model, scan.scans, options, nullptr, &fit).ok());
    FitErrors errors;
    ASSERT_TRUE(CompareWithTruth(s.model, fit.q, fit.T_world_base, NamedJointValues(s.model, q),
                                 T_world_base, Pose::Identity(), &errors)
                    .ok());
    std::printf("  base_alternatives %d: base %.3f mm, %.4f deg%s\n", alternatives,
                1e3 * errors.base_translation, errors.base_rotation / kDeg,
                fit.ok ? "" : (", not ok: " + fit.message).c_str());
    if (alternatives == 0) {  // the premise: alone, the base picks the turned pose
      EXPECT_GT(errors.base_rotation, 179.0 * kDeg);
      EXPECT_FALSE(fit.ok);
      continue;
    }
    EXPECT_LT(errors.base_rotation, 0.01 * kDeg);
    EXPECT_LT(errors.base_translation, 0.0005);
    for (const JointError& e : errors.joints) EXPECT_LT(e.error, 0.001) << e.name;
    EXPECT_TRUE(fit.ok) << fit.message;
  }
}

TEST(ConveyanceFitTest, AutoKindKeepsRobotsArticulated) {
  KinematicModel robot;
  ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                 ModelLoadOptions(), &robot)
                  .ok());
  AssetKind kind = AssetKind::kConveyance;
  ASSERT_TRUE(ChooseAssetKind("auto", robot, &kind).ok());
  EXPECT_EQ(kind, AssetKind::kArticulated);
  ASSERT_TRUE(ChooseAssetKind("conveyance", robot, &kind).ok());
  EXPECT_EQ(kind, AssetKind::kConveyance);
  EXPECT_EQ(FitOptionsFor(kind).base.method, BaseOptions::Method::kArmTips);
  EXPECT_FALSE(ChooseAssetKind("crane", robot, &kind).ok());
}

}  // namespace
}  // namespace edgefit
