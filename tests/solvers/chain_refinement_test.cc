// Whole-chain refinement (solvers/refinement/chain_refinement.h) on a virtual scan of
// the bundled robot without its gun (its balancer a loop closure): the
// derivatives of ChainKinematics are the joints' twists; from a
// sequential-fit-sized error (base 3 mm and 0.1 degrees, every joint 0.3
// degrees) one problem over base and joints brings them back within the
// scan's noise, and the covariance tells the one joint the scan does not
// pin (the round flange's); the covariance alone leaves the estimate as it is.
#include "solvers/refinement/chain_refinement.h"

#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "edgefit/model/joint_values.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/asset_scan.h"
#include "solvers/refinement/chain_kinematics.h"

namespace edgefit {
namespace {

constexpr double kDeg = M_PI / 180.0;

struct RobotScene {
  KinematicModel model;
  std::vector<double> q;  // the truth, every joint
  Pose T_world_base = Pose::Identity();
  ScanSet scans;
  std::vector<SurfaceSamples> samples;  // per link, 8 mm
};

const RobotScene& GetScene() {
  static RobotScene* scene = [] {
    auto* out = new RobotScene;
    CHECK(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                             ModelLoadOptions(), &out->model)
              .ok());
    out->q = out->model.ZeroJoints();
    CHECK(ParseJointAssignments("joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,"
                                "joint_6=0.6",
                                out->model, &out->q)
              .ok());
    CHECK(out->model.ResolveDependentJoints(&out->q).ok());
    out->T_world_base = PoseFromXyzRpy({0.4, -0.3, 0.0}, {0.0, 0.0, 0.5});
    AssetScanOptions options;
    options.scan.spacing = 0.004;
    options.scan.noise_sigma = 0.001;
    options.seed = 3;
    VirtualScan scan;
    CHECK(ScanAsset(out->model, out->q, out->T_world_base, options, &scan, nullptr).ok());
    out->scans = std::move(scan.scans);
    SamplingOptions sampling;
    sampling.spacing = 0.008;
    out->samples = SampleModelSurfaces(out->model, sampling);
    return out;
  }();
  return *scene;
}

// RefineChain on the scene from (*T_world_base, *q) with the given samples
// (point-to-plane).
Status Refine(const std::vector<SurfaceSamples>& samples, const ChainRefinementOptions& options,
              Pose* T_world_base, std::vector<double>* q, ChainRefinementSummary* summary,
              const ResidualOptions& residuals = ResidualOptions()) {
  const RobotScene& s = GetScene();
  CorrespondenceSearch search(&s.scans, nullptr);
  return RefineChain(s.model, s.scans, &search, samples, options, residuals,
                     T_world_base, q, summary);
}

ChainRefinementOptions CovarianceOnly() {
  ChainRefinementOptions options;
  options.refine = false;
  return options;
}

// The truth moved as far as a sequential fit may leave it: base 3 mm and
// 0.1 degrees, every joint 0.3 degrees.
void PerturbedStart(Pose* T_world_base, std::vector<double>* q) {
  const RobotScene& s = GetScene();
  *T_world_base = s.T_world_base * PoseFromXyzRpy({0.003, -0.002, 0.001}, {0, 0, 0.1 * kDeg});
  *q = s.q;
  double sign = 1.0;
  for (const int j : s.model.IndependentJoints()) {
    (*q)[static_cast<size_t>(j)] += sign * 0.3 * kDeg;
    sign = -sign;
  }
}

TEST(ChainKinematicsTest, DerivativesAreTheTwistsOfBaseAndJoints) {
  const RobotScene& s = GetScene();
  const std::vector<int> independent = s.model.IndependentJoints();
  ASSERT_EQ(independent.size(), 6u);
  const double delta[6] = {0, 0, 0, 0, 0, 0};
  std::vector<double> q_independent;
  for (const int j : independent) q_independent.push_back(s.q[static_cast<size_t>(j)]);
  ChainKinematics kinematics(&s.model, s.T_world_base, s.q, delta, q_independent.data());
  kinematics.PrepareForEvaluation(/*evaluate_jacobians=*/true, /*new_evaluation_point=*/true);
  const std::vector<Pose> T = s.model.ForwardKinematics(s.q, s.T_world_base);
  const int flange = s.model.LinkIndex("link_6");
  ASSERT_GE(flange, 0);
  const LinkPoseJacobian& pose = kinematics.At(flange);
  const Eigen::Vector3d t = T[static_cast<size_t>(flange)].translation();
  EXPECT_LT((pose.t - t).norm(), 1e-12);
  const Eigen::Vector3d t_base = s.T_world_base.translation();
  for (int i = 0; i < 3; ++i) {  // base: rotation about world axis i through its origin, shift
    EXPECT_LT((pose.dt[static_cast<size_t>(i)] - Eigen::Vector3d::Unit(i).cross(t - t_base)).norm(),
              1e-6);
    EXPECT_LT((pose.dt[static_cast<size_t>(3 + i)] - Eigen::Vector3d::Unit(i)).norm(), 1e-6);
  }
  for (size_t k = 0; k < independent.size(); ++k) {  // revolute: axis x (t - joint origin)
    const Joint& joint = s.model.joints()[static_cast<size_t>(independent[k])];
    const Pose T_world_joint = T[static_cast<size_t>(joint.parent_link)] * joint.T_parent_joint;
    const Eigen::Vector3d axis = T_world_joint.linear() * joint.axis;
    const Eigen::Vector3d expected = axis.cross(t - T_world_joint.translation());
    EXPECT_LT((pose.dt[6 + k] - expected).norm(), 1e-6) << joint.name;
  }
}

TEST(ChainRefinementTest, BringsBaseAndEveryJointBackTogether) {
  const RobotScene& s = GetScene();
  Pose T_world_base;
  std::vector<double> q;
  PerturbedStart(&T_world_base, &q);
  ChainRefinementSummary summary;
  const Status status = Refine(s.samples, ChainRefinementOptions(), &T_world_base, &q, &summary);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(summary.stop_reason, IcpStopReason::kConverged);
  const Pose error = s.T_world_base.inverse() * T_world_base;
  EXPECT_LT(error.translation().norm(), 0.0005);
  EXPECT_LT(Eigen::AngleAxisd(error.linear()).angle(), 0.02 * kDeg);
  for (const int j : s.model.IndependentJoints()) {
    const size_t k = static_cast<size_t>(j);
    const std::string& name = s.model.joints()[k].name;
    if (name == "joint_6") {
      // Without an end effector the flange is round: the scan hardly pins
      // joint_6, and its standard deviation says so.
      EXPECT_GT(summary.joint_std[k], 0.05 * kDeg);
      continue;
    }
    EXPECT_LT(std::abs(q[k] - s.q[k]), 0.02 * kDeg) << name;
    // The covariance: positive, and below the error the refinement removed
    // (lower bounds: see chain_refinement.h).
    EXPECT_GT(summary.joint_std[k], 0.0) << name;
    EXPECT_LT(summary.joint_std[k], 0.05 * kDeg) << name;
  }
  // Dependent joints (the balancer) follow and carry no deviation of their own.
  for (size_t k = 0; k < q.size(); ++k) {
    if (!s.model.joints()[k].IsIndependent()) {
      EXPECT_TRUE(std::isnan(summary.joint_std[k])) << s.model.joints()[k].name;
    }
  }
  EXPECT_TRUE(summary.covariance_ok);
  EXPECT_GT(summary.sigma, 0.0003);  // about the 1 mm noise
  EXPECT_LT(summary.sigma, 0.002);
}

TEST(ChainRefinementTest, ARobustLossTakesOneSamplePerBlockAndAgrees) {
  const RobotScene& s = GetScene();
  Pose T_world_base;
  std::vector<double> q;
  PerturbedStart(&T_world_base, &q);
  ResidualOptions huber;
  huber.loss = "huber";  // 5 mm: quadratic for the scan's 1 mm noise
  ChainRefinementSummary summary;
  ASSERT_TRUE(Refine(s.samples, ChainRefinementOptions(), &T_world_base, &q, &summary, huber).ok());
  EXPECT_EQ(summary.stop_reason, IcpStopReason::kConverged);
  for (const int j : s.model.IndependentJoints()) {
    const size_t k = static_cast<size_t>(j);
    if (s.model.joints()[k].name == "joint_6") continue;  // the round flange
    EXPECT_LT(std::abs(q[k] - s.q[k]), 0.02 * kDeg) << s.model.joints()[k].name;
  }
}

TEST(ChainRefinementTest, CovarianceAloneKeepsTheEstimate) {
  const RobotScene& s = GetScene();
  Pose T_world_base = s.T_world_base;
  std::vector<double> q = s.q;
  ChainRefinementSummary summary;
  ASSERT_TRUE(Refine(s.samples, CovarianceOnly(), &T_world_base, &q, &summary).ok());
  EXPECT_EQ(summary.iterations, 0);
  EXPECT_LT((T_world_base.matrix() - s.T_world_base.matrix()).norm(), 1e-12);
  for (size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(q[k], s.q[k], 1e-9);
  EXPECT_TRUE(summary.covariance_ok);
  EXPECT_TRUE(std::isfinite(summary.base_translation_std.norm()));
}

TEST(ChainRefinementTest, AJointNoSamplePinsHasNoDeviation) {
  const RobotScene& s = GetScene();
  std::vector<SurfaceSamples> samples = s.samples;
  for (const int l : {s.model.LinkIndex("link_6"), s.model.LinkIndex("tool0")}) {
    if (l >= 0) samples[static_cast<size_t>(l)] = SurfaceSamples();
  }
  Pose T_world_base = s.T_world_base;
  std::vector<double> q = s.q;
  ChainRefinementSummary summary;
  ASSERT_TRUE(Refine(samples, CovarianceOnly(), &T_world_base, &q, &summary).ok());
  // joint_6 moves nothing that has samples: J^T J is singular, and no
  // deviation is made up for it (or for any other joint).
  EXPECT_FALSE(summary.covariance_ok);
  for (const double std : summary.joint_std) EXPECT_TRUE(std::isnan(std));
}

TEST(ChainRefinementTest, RejectsSamplesThatDoNotMatchTheModel) {
  const RobotScene& s = GetScene();
  Pose T_world_base = s.T_world_base;
  std::vector<double> q = s.q;
  ChainRefinementSummary summary;
  const std::vector<SurfaceSamples> too_few(1);
  const Status status = Refine(too_few, ChainRefinementOptions(), &T_world_base, &q, &summary);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("do not match the model"), std::string::npos);
}

}  // namespace
}  // namespace edgefit
