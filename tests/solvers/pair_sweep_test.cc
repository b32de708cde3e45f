// The pair sweep (pair_sweep.h) on a virtual scan of a round upper arm on a
// roll joint with a forearm bent below it: the roll, which the round arm
// alone cannot fix, comes with the bend; the bend is found below a roll, not
// below a joint parallel to it.
#include "solvers/joints/pair_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "edgefit/core/angles.h"
#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/model/urdf_loader.h"
#include "solvers/joints/body.h"
#include "solvers/link_scan_test_util.h"
#include "solvers/registration/scan_visibility.h"

namespace edgefit {
namespace {

// base, a round upper arm on `roll` (z), a forearm box on `bend` (y, or z
// when `parallel`) at the arm's top.
KinematicModel RollAndBend(bool parallel) {
  const std::string urdf =
      ::testing::TempDir() + (parallel ? "/roll_parallel.urdf" : "/roll_bend.urdf");
  std::ofstream(urdf) << R"(<robot name="arm">
  <link name="base"><visual><geometry><box size="0.3 0.3 0.1"/></geometry>
    <origin xyz="0 0 0.05"/></visual></link>
  <link name="upper"><visual><geometry><cylinder radius="0.07" length="0.4"/></geometry>
    <origin xyz="0 0 0.2"/></visual></link>
  <link name="fore"><visual><geometry><box size="0.5 0.09 0.09"/></geometry>
    <origin xyz="0.25 0 0"/></visual></link>
  <joint name="roll" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="bend" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.45"/><axis xyz=")"
                      << (parallel ? "0 0 1" : "0 1 0")
                      << R"("/><limit lower="-2" upper="2" effort="1" velocity="1"/>
  </joint></robot>)";
  KinematicModel model;
  CHECK(LoadModelWithAttachments(urdf, {}, ModelLoadOptions(), &model).ok());
  return model;
}

TEST(PairSweepTest, TheRollComesWithTheBend) {
  const KinematicModel model = RollAndBend(/*parallel=*/false);
  const int roll = model.JointIndex("roll"), bend = model.JointIndex("bend");
  std::vector<double> q_true = model.ZeroJoints();
  q_true[static_cast<size_t>(roll)] = 1.1;
  q_true[static_cast<size_t>(bend)] = -0.6;
  const Pose T_world_base = PoseFromXyzRpy({0.1, 0.2, 0.0}, {0, 0, 0.3});
  TriangleMesh posed;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q_true, T_world_base);
  for (size_t l = 0; l < model.links().size(); ++l) {
    posed.Append(model.links()[l].mesh, T_world_link[l]);
  }
  VirtualScanOptions options;
  options.spacing = 0.004;
  options.noise_sigma = 0.001;
  const VirtualScan scan = testing_util::ScanLinkOnFloor(posed, Pose::Identity(), {}, 3, options);
  CorrespondenceSearch search(&scan.scans, nullptr);
  const ScanVisibility visibility(&scan.scans);
  const JointSweep sweep(&search.lattice(), &visibility);
  SamplingOptions sampling;
  sampling.spacing = 0.01;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);

  const int upper = model.joints()[static_cast<size_t>(roll)].child_link;
  const Body body = MakeBody(model, upper, roll);
  ASSERT_EQ(BendBelow(model, roll, body.links, model.ZeroJoints()), bend);
  PairSweepSummary summary;
  ASSERT_TRUE(SweepPair(model, sweep, JointSweepOptions(), T_world_base, model.ZeroJoints(), body,
                        bend, samples, 1000, 5.0 * kDeg, &summary)
                  .ok());
  EXPECT_NEAR(summary.q, 1.1, 1.0 * kDeg);
  EXPECT_NEAR(summary.q_child, -0.6, 1.0 * kDeg);
  EXPECT_GT(summary.evaluations, 3000);  // the coarse grid: 70 x 47 at 5 deg

  // The round arm alone: every roll costs the same (what the pair sweep is for).
  SurfaceSamples arm;
  AppendBodySamples(body, samples, Pose::Identity(), &arm);
  const auto arm_loss = [&](double value) {
    std::vector<double> q = model.ZeroJoints();
    q[static_cast<size_t>(roll)] = value;
    return sweep.LossAt(arm, model.ForwardKinematics(q, T_world_base)[static_cast<size_t>(upper)],
                        JointSweepOptions());
  };
  EXPECT_NEAR(arm_loss(1.1), arm_loss(-1.0), 0.02 * arm_loss(1.1));
}

TEST(PairSweepTest, NoBendBelowAParallelJointOrALeaf) {
  const KinematicModel model = RollAndBend(/*parallel=*/true);
  const int roll = model.JointIndex("roll"), bend = model.JointIndex("bend");
  const Body upper = MakeBody(model, model.joints()[static_cast<size_t>(roll)].child_link, roll);
  EXPECT_EQ(BendBelow(model, roll, upper.links, model.ZeroJoints()), -1);
  const Body fore = MakeBody(model, model.joints()[static_cast<size_t>(bend)].child_link, bend);
  EXPECT_EQ(BendBelow(model, bend, fore.links, model.ZeroJoints()), -1);
}

}  // namespace
}  // namespace edgefit
