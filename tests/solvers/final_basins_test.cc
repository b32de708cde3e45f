// ChainFitter::CheckFinalBasins (solvers/joints/chain_fitter.h) on an ideal
// scan of the bundled robot with its weld gun: at the true values it finds
// no better basin; from the wrist flipped half a turn (joint_4 + pi,
// -joint_5, joint_6 + pi: the flange where it was, the forearm and wrist
// turned), one joint's better value alone cannot be taken (the others stay
// flipped), so the check follows it as a branch with the joints below fitted
// again and takes the branch: the wrist comes back to the truth.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "edgefit/edges/edge_detector.h"
#include "edgefit/scanner/asset_scan.h"
#include "model/bundled_robot_test_util.h"
#include "solvers/joints/chain_fitter.h"
#include "solvers/registration/scan_visibility.h"

namespace edgefit {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct GunScene {
  KinematicModel model;
  std::vector<double> q;  // the truth, every joint
  Pose T_world_base = Pose::Identity();
  ScanSet scans;
  EdgeDetectionResult edges;
  std::vector<SurfaceSamples> icp_samples, sweep_samples;
};

const GunScene& GetScene() {
  static GunScene* scene = [] {
    auto* out = new GunScene;
    testing_util::LoadBundledRobotWithGun(
        "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.04",
        &out->model, &out->q);
    out->T_world_base = PoseFromXyzRpy({0.4, -0.3, 0.0}, {0.0, 0.0, 0.5});
    AssetScanOptions options;
    options.scan.spacing = 0.004;
    options.scan.noise_sigma = 0.001;
    options.seed = 5;
    VirtualScan scan;
    CHECK(ScanAsset(out->model, out->q, out->T_world_base, options, &scan, nullptr).ok());
    out->scans = std::move(scan.scans);
    CHECK(DetectEdges(out->scans, EdgeDetectionOptions(), &out->edges).ok());
    const CadSampleOptions samples;
    SamplingOptions sampling;
    sampling.spacing = samples.icp_spacing;
    out->icp_samples = SampleModelSurfaces(out->model, sampling);
    sampling.spacing = samples.sweep_spacing;
    out->sweep_samples = SampleModelSurfaces(out->model, sampling);
    return out;
  }();
  return *scene;
}

// CheckFinalBasins(take = true) from q on the scene: *moved, and q after.
void CheckFrom(std::vector<double>* q, bool* moved) {
  const GunScene& s = GetScene();
  CorrespondenceSearch search(&s.scans, nullptr);
  const ScanVisibility visibility(&s.scans);
  WeightedIcp icp(&s.scans, &search, &s.edges.normals);
  const JointSweep sweep(&search.lattice(), &visibility);
  const ChainOptions options;
  const CadSampleOptions samples;
  ChainFitter chain(s.model, options, samples, s.icp_samples, s.sweep_samples, &icp, &sweep,
                    [](const std::string& line) { LOG(INFO) << line; });
  std::vector<JointRecord> records;
  for (const int joint : s.model.joint_order()) {
    if (!s.model.joints()[static_cast<size_t>(joint)].IsIndependent()) continue;
    JointRecord record;
    record.joint = joint;
    records.push_back(record);
  }
  ASSERT_TRUE(chain.CheckFinalBasins(s.T_world_base, /*take=*/true, q, &records, moved).ok());
  for (const JointRecord& record : records) EXPECT_FALSE(record.better_elsewhere);
}

double Error(const std::vector<double>& q, const std::string& joint) {
  const GunScene& s = GetScene();
  const size_t j = static_cast<size_t>(s.model.JointIndex(joint));
  return std::abs(std::remainder(q[j] - s.q[j], 2.0 * M_PI));
}

TEST(FinalBasinsTest, FindNothingBetterAtTheTruth) {
  std::vector<double> q = GetScene().q;
  bool moved = true;
  CheckFrom(&q, &moved);
  EXPECT_FALSE(moved);
  EXPECT_EQ(q, GetScene().q);
}

TEST(FinalBasinsTest, BringAFlippedWristBack) {
  const GunScene& s = GetScene();
  std::vector<double> q = s.q;
  q[static_cast<size_t>(s.model.JointIndex("joint_4"))] += M_PI;
  q[static_cast<size_t>(s.model.JointIndex("joint_5"))] *= -1.0;
  q[static_cast<size_t>(s.model.JointIndex("joint_6"))] -= M_PI;
  bool moved = false;
  CheckFrom(&q, &moved);
  EXPECT_TRUE(moved);
  for (const std::string joint : {"joint_4", "joint_5", "joint_6"}) {
    EXPECT_LT(Error(q, joint), 0.5 * kDeg)
        << joint << " is " << Error(q, joint) / kDeg << " deg off";
  }
  EXPECT_LT(Error(q, "gun_joint"), 0.003);
}

}  // namespace
}  // namespace edgefit
