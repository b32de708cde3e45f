// A real robot seen by a real depth camera: frames of ../shared/data/real/
// lbr_med7_zed2i (a KUKA LBR Med7 on a 32 degree wedge, a ZED 2i stereo
// camera, 540 x 960), fitted with default options and its camera_info, as a
// user would. Scored against the joint values the robot recorded and the
// reference base poses of published camera-to-robot registrations (which
// differ among themselves by about a centimetre). Fails if the calibration
// (every joint given; frames 002 and 003) or the fit of every joint (frame
// 003, and frame 004: the robot beside clutter) regresses; the figures of
// every frame are in BENCHMARK.md (scripts/real_frames.py). Skips without
// ../shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "edgefit/core/angles.h"
#include "edgefit/io/camera_info.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/model/composition.h"
#include "edgefit/pipeline/fit.h"

namespace edgefit {
namespace {

struct RealFrame {
  KinematicModel model;
  ScanSet scans;
  nlohmann::json truth;
  Pose T_world_base_reference;
};

// Loads frame `stem` of the Med7 set; false (the test skips) without it.
bool LoadFrame(const std::string& stem, RealFrame* frame) {
  const std::string set = std::string(EDGEFIT_SHARED_DIR) + "/data/real/lbr_med7_zed2i/";
  if (!std::filesystem::exists(set + "frames/" + stem + ".pcd")) return false;
  ReadOptions read;
  EXPECT_TRUE(ReadCameraInfo(set + "camera_info.yaml", &read.camera).ok());
  EXPECT_TRUE(ReadScans(set + "frames/" + stem + ".pcd", read, &frame->scans).ok());
  EXPECT_TRUE(
      LoadModelWithAttachments(set + "robot/med7.urdf", {}, ModelLoadOptions(), &frame->model)
          .ok());
  std::ifstream in(set + "truth/" + stem + ".json");
  frame->truth = nlohmann::json::parse(in);
  const auto& t = frame->truth["T_world_base_reference"];
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = t[r][c].get<double>();
  }
  frame->T_world_base_reference = Pose(m);
  return true;
}

double PositionErrorMm(const Pose& a, const Pose& b) {
  return 1e3 * (a.translation() - b.translation()).norm();
}

double AngleDeg(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle() / kDeg;
}

// The calibration (every joint given) of frame `stem`: the base within mm
// and deg of the reference, and the camera's noise measured.
void Calibrate(const std::string& stem, double mm_bound, double deg_bound) {
  RealFrame frame;
  if (!LoadFrame(stem, &frame)) GTEST_SKIP() << "../shared/data/real absent";
  FitOptions options;
  for (const auto& [name, value] : frame.truth["joints"].items()) {
    options.known_joints.emplace_back(name, value.get<double>());
  }
  FitResult fit;
  ASSERT_TRUE(Fit(frame.model, frame.scans, options, nullptr, &fit).ok());
  const double mm = PositionErrorMm(fit.T_world_base, frame.T_world_base_reference);
  const double deg = AngleDeg(fit.T_world_base, frame.T_world_base_reference);
  std::printf("  frame %s calibration: base %.1f mm, %.2f deg from the reference; noise %.1f mm\n",
              stem.c_str(), mm, deg, 1e3 * fit.noise_sigma);
  EXPECT_LT(mm, mm_bound) << "frame " << stem;
  EXPECT_LT(deg, deg_bound) << "frame " << stem;
  EXPECT_GT(fit.noise_scale, 1.0);  // a stereo camera's centimetre is measured
}

TEST(RealFrameFitTest, CalibrationFromTheRecordedJoints) {
  Calibrate("003", 15.0, 2.5);  // measured 3.3 mm, 1.69 deg (2026-11-29)
}

// Frame 002's base is voted for on the whole slim arm: at 5 % of its
// length (5.8 cm voxels) it was voted onto clutter 1.7 m away and said ok.
TEST(RealFrameFitTest, CalibrationOfTheSlimArmSeenEdgeOn) {
  Calibrate("002", 25.0, 2.5);  // measured 11.2 mm, 1.31 deg (2026-11-29)
}

// Every joint fitted on frame `stem` with default options: the base (its
// axis: a round base's yaw goes with lbr_A1) within mm / deg of the
// reference, no joint said ok more than 4 degrees off; *errors: each
// joint's error [rad] by name.
void FitEveryJoint(const std::string& stem, double mm_bound, double tilt_bound_deg,
                   std::map<std::string, double>* errors) {
  RealFrame frame;
  if (!LoadFrame(stem, &frame)) GTEST_SKIP() << "../shared/data/real absent";
  FitResult fit;
  ASSERT_TRUE(Fit(frame.model, frame.scans, FitOptions(), nullptr, &fit).ok());
  const double mm = PositionErrorMm(fit.T_world_base, frame.T_world_base_reference);
  const double tilt_deg =
      std::acos(std::clamp(
          fit.T_world_base.rotation().col(2).dot(frame.T_world_base_reference.rotation().col(2)),
          -1.0, 1.0)) /
      kDeg;
  std::printf("  frame %s, every joint: base %.1f mm from the reference, its axis %.2f deg\n",
              stem.c_str(), mm, tilt_deg);
  EXPECT_LT(mm, mm_bound);
  EXPECT_LT(tilt_deg, tilt_bound_deg);
  for (const BodyQuality& body : fit.bodies) {
    if (body.joint.empty() || !frame.truth["joints"].contains(body.joint)) continue;
    const double q = fit.q[static_cast<size_t>(frame.model.JointIndex(body.joint))];
    const double error =
        std::remainder(q - frame.truth["joints"][body.joint].get<double>(), 2 * M_PI);
    (*errors)[body.joint] = error;
    std::printf("  %s: %.2f deg off, %s\n", body.joint.c_str(), error / kDeg,
                JointVerdictName(body.verdict));
    if (body.verdict == JointVerdict::kOk) {
      EXPECT_LT(std::abs(error), 4.0 * kDeg) << body.joint << " said ok";
    }
  }
}

TEST(RealFrameFitTest, EveryJointFittedNothingConfidentlyWrong) {
  std::map<std::string, double> errors;
  // Measured 4.3 mm, axis 2.1 deg (2026-11-29; 6.3 mm and 3.2 deg while
  // coverings were sought on noisy frames).
  FitEveryJoint("003", 15.0, 4.0, &errors);
  if (errors.empty()) return;  // skipped
  // Measured 1.6, 0.3, 0.6, 1.5, 1.7 deg off (2026-11-29). The wrist: with
  // the pair sweep (pair_sweep.h); without it 141 and 60 deg (2026-11-28);
  // while coverings were sought, lbr_A2 and A3 2.9 and 3.0 deg.
  for (const char* joint : {"lbr_A2", "lbr_A3", "lbr_A4", "lbr_A5", "lbr_A6"}) {
    EXPECT_LT(std::abs(errors[joint]), 4.0 * kDeg) << joint;
  }
}

// Frame 004: the arm folded over its base, another white arm and clutter
// 2 m away. Found by the voted poses' evidence (pose_evidence.h): measured
// 12.6 mm, axis 0.25 deg (2026-11-30; 11.0 mm, 1.0 deg before the upright
// search ran at the frame's noise levels); before that evidence, the fit
// stood in the clutter.
TEST(RealFrameFitTest, TheRobotIsFoundBesideTheClutter) {
  std::map<std::string, double> errors;
  FitEveryJoint("004", 25.0, 2.0, &errors);
}

}  // namespace
}  // namespace edgefit
