// The robot pipeline end to end (paper Sec. 5) on a small virtual scan: the
// bundled robot with its weld gun and accessories (harnesses, clamps), a
// floor and clutter, 3 scanners, 4 mm spacing (about 1.9 M points), 1 mm
// noise. Fails if accuracy regresses (the accuracy bar for the full 1.7 mm
// scenes is in BENCHMARK.md), or if the fit depends on the thread count.
// The scans that do not hold the model are in negative_fit_test.cc.
#include <glog/logging.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/pipeline/model_points.h"
#include "edgefit/pipeline/result_json.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/truth.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "model/bundled_robot_test_util.h"
#include "pipeline/robot_scene.h"

namespace edgefit {
namespace {

using testing_util::RobotScene;
const RobotScene& GetScene() { return testing_util::GetRobotScene(); }

FitErrors FitScene(const ScanSet& scans, FitResult* fit) {
  const RobotScene& s = GetScene();
  const Status status = Fit(s.model, scans, FitOptions(), nullptr, fit);
  EXPECT_TRUE(status.ok()) << status.message();
  FitErrors errors;
  CHECK(CompareWithTruth(s.model, fit->q, fit->T_world_base, NamedJointValues(s.model, s.q),
                         s.T_world_base, Pose::Identity(), &errors, fit->base_symmetry)
            .ok());
  return errors;
}

// The scene fitted once with 2 threads, shared by the tests that read it.
const FitResult& TwoThreadFit(FitErrors* errors = nullptr) {
  static FitErrors* fit_errors = new FitErrors;
  static FitResult* fit = [] {
    auto* out = new FitResult;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(2);
    *fit_errors = FitScene(GetScene().scans, out);
    omp_set_num_threads(threads);
    return out;
  }();
  if (errors != nullptr) *errors = *fit_errors;
  return *fit;
}

TEST(RobotFitTest, RecoversBaseAndJointsWithAccessories) {
  const RobotScene& s = GetScene();
  FitErrors errors;
  const FitResult& fit = TwoThreadFit(&errors);
  std::printf("  %zu points; base %.3f mm %.4f deg; %.2f s\n", s.scans.TotalValid(),
              errors.base_translation * 1e3, errors.base_rotation / kDeg, fit.timings.total);
  double sum = 0.0, max = 0.0;
  int revolute = 0;
  for (const JointError& e : errors.joints) {
    std::printf("  %-24s error %.4f %s\n", e.name.c_str(),
                e.prismatic ? e.error * 1e3 : e.error / kDeg, e.prismatic ? "mm" : "deg");
    if (e.prismatic) {  // the gun's electrode: a thin rod along its own axis
      EXPECT_LT(e.error, 0.0015) << e.name;
      continue;
    }
    sum += e.error;
    max = std::max(max, e.error);
    ++revolute;
  }
  // Every body of the robot matches the scan (the electrode, thin and
  // coarsely sampled at this spacing, may be flagged).
  for (const BodyQuality& b : fit.bodies) {
    if (b.link != "gun_electrode") {
      EXPECT_TRUE(b.ok) << b.link;
    }
    EXPECT_FALSE(b.ambiguous) << b.link;
  }
  // Measured at 4 mm spacing: base 0.031 mm, 0.012 deg; revolute joints
  // mean 0.0036 deg (the balancer's included), max 0.012 deg (joint_1); gun
  // 0.41 mm. About three times that fails (the base's bounds are older).
  // The accuracy bar of BENCHMARK.md (revolute mean 0.05 deg, p95 0.15 deg)
  // is for its 1.7 mm scans.
  EXPECT_LT(errors.base_translation, 0.0001);
  EXPECT_LT(errors.base_rotation, 0.03 * kDeg);
  EXPECT_LT(sum / revolute, 0.025 * kDeg);
  EXPECT_LT(max, 0.05 * kDeg);
}

TEST(RobotFitTest, SameResultForAnyThreadCount) {
  const RobotScene& s = GetScene();
  const FitResult& two = TwoThreadFit();
  FitResult one;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  FitScene(s.scans, &one);
  omp_set_num_threads(threads);
  EXPECT_TRUE(one.T_world_base.matrix() == two.T_world_base.matrix());
  EXPECT_EQ(one.q, two.q);
}

// --out_background: the points of the model at its true pose are found
// (the robot's and the gun's), little else (the floor under the base plate,
// clamps and harness roots that touch the links).
TEST(RobotFitTest, ModelPointsAreTheRobotsPoints) {
  const RobotScene& s = GetScene();
  std::vector<std::vector<uint8_t>> marks;
  ASSERT_TRUE(
      MarkModelPoints(s.scans, s.model, s.q, s.T_world_base, ModelPointsOptions(), &marks).ok());
  size_t robot = 0, robot_marked = 0, other = 0, other_marked = 0;
  for (size_t k = 0; k < s.scans.scans.size(); ++k) {
    for (size_t cell = 0; cell < s.scans.scans[k].size(); ++cell) {
      if (!s.scans.scans[k].IsValid(cell)) continue;
      const bool is_robot = IsLinkLabel(s.labels[k][cell]);
      (is_robot ? robot : other) += 1;
      (is_robot ? robot_marked : other_marked) += marks[k][cell];
    }
  }
  const double found = static_cast<double>(robot_marked) / static_cast<double>(robot);
  const double wrong = static_cast<double>(other_marked) / static_cast<double>(other);
  std::printf("  %zu robot points, %.2f%% found; %zu others, %.3f%% taken\n", robot, 100.0 * found,
              other, 100.0 * wrong);
  EXPECT_GT(found, 0.995);
  EXPECT_LT(wrong, 0.01);
  ScanSet background = s.scans;
  EXPECT_EQ(RemoveMarkedPoints(marks, &background), robot_marked + other_marked);
  EXPECT_EQ(background.TotalValid(), s.scans.TotalValid() - robot_marked - other_marked);
}

// --init: the hint gives x, y and yaw only; the base height comes from the
// scan's floor, wherever the scan's origin is (here 1.3 m above the floor,
// as in a scanner-centred frame). The hint is 3 cm and 3 degrees off.
TEST(RobotFitTest, BaseHintTakesTheHeightFromTheFloor) {
  const RobotScene& s = GetScene();
  ScanSet lowered = s.scans;
  const Pose T_shift = PoseFromXyzRpy({0.0, 0.0, -1.3}, {0.0, 0.0, 0.0});
  for (OrganizedScan& scan : lowered.scans)
    scan.set_T_world_scanner(T_shift * scan.T_world_scanner());
  FitOptions options;
  options.base.has_initial = true;
  options.base.T_world_base_initial = PoseFromXyYaw(0.53, -0.17, 18.0 * kDeg);
  FitResult fit;
  ASSERT_TRUE(Fit(s.model, lowered, options, nullptr, &fit).ok());
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(s.model, fit.q, fit.T_world_base, NamedJointValues(s.model, s.q),
                               T_shift * s.T_world_base, Pose::Identity(), &errors,
                               fit.base_symmetry)
                  .ok());
  EXPECT_TRUE(fit.ok) << fit.message;
  EXPECT_LT(errors.base_translation, 0.0001);
  EXPECT_LT(errors.base_rotation, 0.03 * kDeg);
  for (const JointError& e : errors.joints) {
    EXPECT_LT(e.error, e.prismatic ? 0.002 : 0.05 * kDeg) << e.name;
  }
}

// The bundled robot bare (no gun): its round flange is unobservable,
// reported at its zero without a spread, and the fit is ok with every other
// joint pinned.
TEST(RobotFitTest, BareFlangeIsUnobservableAndTheFitOk) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                 ModelLoadOptions(), &model)
                  .ok());
  std::vector<double> q = model.ZeroJoints();
  ASSERT_TRUE(
      ParseJointAssignments(
          "joint_1=-0.4,joint_2=0.3,joint_3=0.2,joint_4=0.8,joint_5=-0.7,joint_6=1.9", model, &q)
          .ok());
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  const Pose T_world_base = PoseFromXyzRpy({0.3, 0.1, 0.0}, {0.0, 0.0, -20.0 * kDeg});
  AssetScanOptions options;
  options.scan.spacing = 0.004;
  options.seed = 9;
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(model, q, T_world_base, options, &scan, nullptr).ok());
  FitResult fit;
  ASSERT_TRUE(Fit(model, scan.scans, FitOptions(), nullptr, &fit).ok());
  EXPECT_TRUE(fit.ok) << fit.message;
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(model, fit.q, fit.T_world_base, NamedJointValues(model, q),
                               T_world_base, Pose::Identity(), &errors, fit.base_symmetry)
                  .ok());
  for (const BodyQuality& b : fit.bodies) {
    if (b.joint.empty()) continue;
    const bool flange = b.joint == "joint_6";
    EXPECT_EQ(b.verdict, flange ? JointVerdict::kUnobservable : JointVerdict::kOk) << b.joint;
  }
  const size_t j6 = static_cast<size_t>(model.JointIndex("joint_6"));
  EXPECT_EQ(fit.q[j6], 0.0);  // the convention
  const nlohmann::json result = FitResultJson(model, AssetKind::kArticulated, FitOptions(), fit);
  EXPECT_TRUE(result["joint_std"]["joint_6"].is_null()) << result["joint_std"].dump();
  EXPECT_EQ(result["joint_status"]["joint_6"]["verdict"], "unobservable");
  EXPECT_TRUE(result["joint_status"]["joint_6"]["std"].is_null());
  EXPECT_EQ(result["joint_status"]["joint_5"]["verdict"], "ok");
  EXPECT_EQ(result["joint_status"]["joint_5"]["std"], result["joint_std"]["joint_5"]);
  EXPECT_TRUE(result["joint_status"]["joint_5"]["std"].is_number());
  for (const JointError& e : errors.joints) {
    if (e.name != "joint_6") {
      EXPECT_LT(e.error, 0.05 * kDeg) << e.name;
    }
  }
}

}  // namespace
}  // namespace edgefit
