// e2e: the bundled robot with its gun seen by a virtual depth camera
// (scanner/depth_camera.h: a 960 x 540 stereo-like camera about 3 m away, depth
// noise 2.5 mm at 1 m growing with depth^2 and correlated over 12 pixels,
// flying pixels), fitted with the default options as `edgefit fit` fits a
// real frame: no joint said ok more than 4 degrees off, none on a base that
// was not found, and such a base not ok itself. The base is not always
// found on such frames (benchmarks/results/2026-11-29-noisy-sections.md):
// this scene's was voted onto a round pillar 4 m away until the upright
// search's section corners were scaled to the frame's noise; now it is
// found 15 mm off (tilted 5 degrees).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/angles.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

TEST(DepthFrameFitTest, TheRobotSeenByADepthCamera) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun(
      "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
      &model, &q);
  AssetScanOptions options;
  options.scan.camera.width = 960;
  options.scan.camera.height = 540;
  options.scan.camera.camera.fx = options.scan.camera.camera.fy = 534.6;
  options.scan.camera.camera.cx = 479.5;
  options.scan.camera.camera.cy = 269.5;
  options.scan.camera.sigma_at_1m = 0.0025;
  options.scan.beam = options.scan.camera.FlyingPixelBeam();
  options.scan.max_range = 6.0;
  options.T_world_scanners = {PoseFromXyzRpy({3.0, 1.0, 1.5}, {0, 0, 0})};  // looks at the robot
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(model, q, Pose::Identity(), options, &scan, nullptr).ok());
  ASSERT_EQ(scan.scans.scans[0].lattice().model(), ScanLattice::Model::kProjective);

  FitResult fit;
  ASSERT_TRUE(Fit(model, scan.scans, FitOptions(), nullptr, &fit).ok());
  FitErrors errors;
  ASSERT_TRUE(CompareWithTruth(model, fit.q, fit.T_world_base, NamedJointValues(model, q),
                               Pose::Identity(), Pose::Identity(), &errors, fit.base_symmetry)
                  .ok());
  MarkUnobservableJoints(fit.bodies, &errors);
  std::printf("  %zu points, noise %.1f mm; base %.1f mm %.2f deg; %s\n", scan.scans.TotalValid(),
              1e3 * fit.noise_sigma, 1e3 * errors.base_translation, errors.base_rotation / kDeg,
              fit.message.c_str());
  // Whatever the frame lets it find, nothing confident is wrong: a joint
  // said ok is within 4 degrees, and a base off by more than 6 cm (not
  // found: the round pillars of the clutter look like its round base) is
  // not ok itself (most of it lies behind scanned surfaces), has no joint
  // said ok, and the fit is said not ok.
  const bool found = errors.base_translation < 0.06;
  const BodyQuality& base = fit.bodies.front();
  std::printf("  base %s: %zu of %zu samples facing the camera in view\n",
              JointVerdictName(base.verdict), base.visible, base.visible + base.occluded);
  if (!found) {
    EXPECT_NE(base.verdict, JointVerdict::kOk) << "a base that is not there said ok";
  }
  int ok = 0;
  for (const BodyQuality& b : fit.bodies) {
    if (b.verdict != JointVerdict::kOk || b.joint.empty()) continue;
    const size_t j = static_cast<size_t>(model.JointIndex(b.joint));
    const double error = std::abs(std::remainder(fit.q[j] - q[j], 2.0 * M_PI));
    std::printf("  %s ok, %.2f deg off (std %.2f deg)\n", b.joint.c_str(), error / kDeg,
                b.joint_std / kDeg);
    EXPECT_LT(error, 4.0 * kDeg) << b.joint << " said ok";
    ++ok;
  }
  if (!found) {
    EXPECT_EQ(ok, 0) << "joints said ok on a base that is not there";
    EXPECT_FALSE(fit.ok);
  }
}

}  // namespace
}  // namespace edgefit
