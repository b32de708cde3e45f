// Weighted ICP engine (solvers/registration/weighted_icp.h) on synthetic clouds with known
// transforms: the target is the CAD samples themselves, posed by the truth
// (and perturbed by noise), so the exact answer is known.
#include "solvers/registration/weighted_icp.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "edgefit/core/angles.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/icp_test_util.h"

namespace edgefit {
namespace {

using testing_util::CloudScan;
using testing_util::LinkMesh;
using testing_util::RotationErrorRad;
using testing_util::TranslationError;

struct Synthetic {
  SurfaceSamples samples;  // link frame
  ScanSet scans;
  CellWeights weights;
};

// Samples every 6 mm (~11 k points) and a target = T_world_link * samples +
// N(0, sigma^2) per axis. Weights 10 on every 7th point, like edges.
Synthetic MakeSynthetic(const Pose& T_world_link, double sigma) {
  Synthetic s;
  s.samples = SampleMeshSurface(LinkMesh(), 0.006, 5);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, sigma > 0.0 ? sigma : 1.0);
  std::vector<Eigen::Vector3d> target;
  for (const Eigen::Vector3f& p : s.samples.points) {
    Eigen::Vector3d q = T_world_link * p.cast<double>();
    if (sigma > 0.0) q += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    target.push_back(q);
  }
  s.scans = CloudScan(target);
  s.weights.assign(1, std::vector<float>(target.size(), 1.0f));
  for (size_t i = 0; i < target.size(); i += 7) s.weights[0][i] = 10.0f;
  return s;
}

WeightedIcpOptions KdTreeOptions() {
  WeightedIcpOptions options;
  options.correspondence.use_lattice = false;                 // unorganized synthetic cloud
  options.visibility = WeightedIcpOptions::Visibility::kAll;  // all samples are in the target
  options.final_gate = 0.05;                                  // no outliers: a fixed gate
  options.max_iterations = 100;
  options.convergence_displacement = 1e-9;  // recovery to 1e-6 is asserted
  return options;
}

struct FitOutput {
  LinkState state;
  WeightedIcpSummary summary;
};

FitOutput RunFit(const Synthetic& s, const LinkMotion& motion, const WeightedIcpOptions& options,
                 const LinkState& initial, const ResidualOptions& residuals = ResidualOptions()) {
  CorrespondenceSearch search(&s.scans, &s.weights);
  WeightedIcp icp(&s.scans, &search, nullptr, residuals);
  FitOutput out;
  out.state = initial;
  const Status status = icp.Fit(s.samples, motion, options, &out.state, &out.summary);
  EXPECT_TRUE(status.ok()) << status.message();
  std::printf("  %s\n", out.summary.BriefReport().c_str());
  return out;
}

// Far from the origin and rotated by ~2.9 rad, near the angle-axis
// singularity at pi, where the rotation manifold matters.
const Pose kTrueFreePose = PoseFromXyzRpy({4.0, -2.5, 1.2}, {2.9, -0.3, 1.1});

TEST(WeightedIcpTest, FreePoseRecoveredExactlyWithoutNoise) {
  const Synthetic s = MakeSynthetic(kTrueFreePose, 0.0);
  LinkState initial;
  initial.T_world_link = kTrueFreePose * PoseFromXyzRpy({0.02, -0.015, 0.01}, {0.03, -0.04, 0.05});
  const FitOutput out = RunFit(s, LinkMotion::Free(), KdTreeOptions(), initial);
  EXPECT_EQ(out.summary.stop_reason, IcpStopReason::kConverged);
  EXPECT_LT(TranslationError(out.state.T_world_link, kTrueFreePose), 1e-6);
  EXPECT_LT(RotationErrorRad(out.state.T_world_link, kTrueFreePose), 1e-6);
  EXPECT_EQ(out.summary.inliers, s.samples.size());
  EXPECT_EQ(out.summary.visible_points, s.samples.size());
  EXPECT_LT(out.summary.rms, 1e-6);
}

// A revolute and a prismatic joint, both parameterisations, each started
// 4 degrees / 3 cm off: recovered to 1e-6 without noise.
struct JointCase {
  std::string name;
  LinkMotion::Type type;
  JointParameterization parameterization;
};

class JointRecoveryTest : public ::testing::TestWithParam<JointCase> {};

LinkMotion TestJoint(LinkMotion::Type type) {
  LinkMotion motion;
  motion.type = type;
  motion.T_world_joint = PoseFromXyzRpy({1.5, 0.4, 0.9}, {0.3, 0.2, -0.7});
  motion.axis_joint = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  motion.has_limits = true;
  motion.lower = type == LinkMotion::Type::kRevolute ? -3.0 : -0.5;
  motion.upper = type == LinkMotion::Type::kRevolute ? 3.0 : 0.5;
  return motion;
}

TEST_P(JointRecoveryTest, RecoveredExactlyWithoutNoise) {
  const JointCase& c = GetParam();
  const LinkMotion motion = TestJoint(c.type);
  const bool revolute = c.type == LinkMotion::Type::kRevolute;
  const double q_true = revolute ? 1.2 : 0.21;
  const Synthetic s = MakeSynthetic(motion.PoseAt(q_true), 0.0);
  ResidualOptions residuals;
  residuals.parameterization = c.parameterization;
  LinkState initial;
  initial.q = q_true + (revolute ? 4.0 * kDeg : 0.03);
  const FitOutput out = RunFit(s, motion, KdTreeOptions(), initial, residuals);
  EXPECT_EQ(out.summary.stop_reason, IcpStopReason::kConverged);
  EXPECT_NEAR(out.state.q, q_true, 1e-6);
  EXPECT_LT(TranslationError(out.state.T_world_link, motion.PoseAt(q_true)), 1e-6);
  EXPECT_LT(RotationErrorRad(out.state.T_world_link, motion.PoseAt(q_true)), 1e-6);
  EXPECT_LT(out.summary.projection_shift, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(
    Joints, JointRecoveryTest,
    ::testing::Values(JointCase{"RevoluteJointSpace", LinkMotion::Type::kRevolute,
                                JointParameterization::kJointSpace},
                      JointCase{"RevolutePosePenalty", LinkMotion::Type::kRevolute,
                                JointParameterization::kPoseWithPenalties},
                      JointCase{"PrismaticJointSpace", LinkMotion::Type::kPrismatic,
                                JointParameterization::kJointSpace},
                      JointCase{"PrismaticPosePenalty", LinkMotion::Type::kPrismatic,
                                JointParameterization::kPoseWithPenalties}),
    [](const ::testing::TestParamInfo<JointCase>& info) { return info.param.name; });

// With noise sigma per axis on N targets, least squares with the right
// correspondences has a translation error of about sigma / sqrt(N) per axis
// and a rotation error of about sigma / (sqrt(N) r), r the RMS lever arm
// (~0.15 m). The bound allows 5 times that: nearest-neighbour matches
// under noise are not always the right ones.
TEST(WeightedIcpTest, FreePoseWithinNoiseBound) {
  const double sigma = 0.001;
  const Synthetic s = MakeSynthetic(kTrueFreePose, sigma);
  const double n = static_cast<double>(s.samples.size());
  LinkState initial;
  initial.T_world_link = kTrueFreePose * PoseFromXyzRpy({0.01, 0.01, -0.01}, {0.02, 0.02, 0.02});
  const FitOutput out = RunFit(s, LinkMotion::Free(), KdTreeOptions(), initial);
  const double t_error = TranslationError(out.state.T_world_link, kTrueFreePose);
  const double r_error = RotationErrorRad(out.state.T_world_link, kTrueFreePose);
  std::printf("  noise %.1f mm, %zu points: translation error %.4f mm, rotation %.5f deg\n",
              sigma * 1e3, s.samples.size(), t_error * 1e3, r_error / kDeg);
  EXPECT_LT(t_error, 5.0 * std::sqrt(3.0) * sigma / std::sqrt(n));
  EXPECT_LT(r_error, 5.0 * std::sqrt(3.0) * sigma / (std::sqrt(n) * 0.15));
  // Every target is within a few sigma of its source: all are inliers, and
  // the RMS distance is below the noise (nearest points, not the true ones).
  EXPECT_EQ(out.summary.inliers, s.samples.size());
  EXPECT_LT(out.summary.rms, std::sqrt(3.0) * sigma);
}

TEST_P(JointRecoveryTest, WithinNoiseBound) {
  const JointCase& c = GetParam();
  const LinkMotion motion = TestJoint(c.type);
  const bool revolute = c.type == LinkMotion::Type::kRevolute;
  const double q_true = revolute ? -0.6 : -0.12;
  const double sigma = 0.001;
  const Synthetic s = MakeSynthetic(motion.PoseAt(q_true), sigma);
  ResidualOptions residuals;
  residuals.parameterization = c.parameterization;
  LinkState initial;
  initial.q = q_true - (revolute ? 3.0 * kDeg : 0.02);
  const FitOutput out = RunFit(s, motion, KdTreeOptions(), initial, residuals);
  const double error = std::abs(out.state.q - q_true);
  std::printf("  %s: joint error %.6f %s\n", c.name.c_str(), revolute ? error / kDeg : error * 1e3,
              revolute ? "deg" : "mm");
  const double bound = 5.0 * std::sqrt(3.0) * sigma /
                       (std::sqrt(static_cast<double>(s.samples.size())) * (revolute ? 0.15 : 1.0));
  EXPECT_LT(error, bound);
}

TEST(WeightedIcpTest, SameResultForAnyThreadCount) {
  const Synthetic s = MakeSynthetic(kTrueFreePose, 0.001);
  LinkState initial;
  initial.T_world_link = kTrueFreePose * PoseFromXyzRpy({0.01, 0.0, 0.0}, {0.0, 0.02, 0.0});
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FitOutput one = RunFit(s, LinkMotion::Free(), KdTreeOptions(), initial);
  omp_set_num_threads(2);
  const FitOutput two = RunFit(s, LinkMotion::Free(), KdTreeOptions(), initial);
  omp_set_num_threads(threads);
  EXPECT_TRUE(one.state.T_world_link.matrix() == two.state.T_world_link.matrix());
  EXPECT_EQ(one.summary.iterations, two.summary.iterations);
  EXPECT_EQ(one.summary.final_cost, two.summary.final_cost);
}

using PlaneNormals = WeightedIcpOptions::PlaneNormals;

// Point-to-plane with the samples' own normals or the true target normals
// converges to the same pose.
TEST(WeightedIcpTest, PointToPlaneRecoversFreePose) {
  const Synthetic s = MakeSynthetic(kTrueFreePose, 0.0);
  std::vector<std::vector<Eigen::Vector3f>> normals(1);
  for (const Eigen::Vector3f& n : s.samples.normals) {
    normals[0].push_back((kTrueFreePose.linear() * n.cast<double>()).cast<float>());
  }
  for (const PlaneNormals source : {PlaneNormals::kModel, PlaneNormals::kScan}) {
    CorrespondenceSearch search(&s.scans, &s.weights);
    WeightedIcp icp(&s.scans, &search, source == PlaneNormals::kScan ? &normals : nullptr);
    WeightedIcpOptions options = KdTreeOptions();
    options.point_to_plane = true;
    options.plane_normals = source;
    LinkState state;
    state.T_world_link = kTrueFreePose * PoseFromXyzRpy({0.01, -0.01, 0.005}, {0.02, 0.01, -0.02});
    WeightedIcpSummary summary;
    ASSERT_TRUE(icp.Fit(s.samples, LinkMotion::Free(), options, &state, &summary).ok());
    EXPECT_EQ(summary.stop_reason, IcpStopReason::kConverged) << summary.BriefReport();
    EXPECT_LT(TranslationError(state.T_world_link, kTrueFreePose), 1e-6);
    EXPECT_LT(RotationErrorRad(state.T_world_link, kTrueFreePose), 1e-6);
  }
}

// Joint-space point-to-plane (joint_point_to_plane_cost.h) with either
// normal source recovers revolute and prismatic joints exactly, in fewer
// iterations than point-to-point.
TEST(WeightedIcpTest, PointToPlaneRecoversJoints) {
  for (const LinkMotion::Type type : {LinkMotion::Type::kRevolute, LinkMotion::Type::kPrismatic}) {
    const LinkMotion motion = TestJoint(type);
    const bool revolute = type == LinkMotion::Type::kRevolute;
    const double q_true = revolute ? 1.2 : 0.21;
    const Pose T_true = motion.PoseAt(q_true);
    const Synthetic s = MakeSynthetic(T_true, 0.0);
    std::vector<std::vector<Eigen::Vector3f>> normals(1);
    for (const Eigen::Vector3f& n : s.samples.normals) {
      normals[0].push_back((T_true.linear() * n.cast<double>()).cast<float>());
    }
    CorrespondenceSearch search(&s.scans, &s.weights);
    WeightedIcp icp(&s.scans, &search, &normals);
    WeightedIcpOptions options = KdTreeOptions();
    LinkState point_state;
    point_state.q = q_true + (revolute ? 4.0 * kDeg : 0.03);
    WeightedIcpSummary point;
    ASSERT_TRUE(icp.Fit(s.samples, motion, options, &point_state, &point).ok());
    options.point_to_plane = true;
    for (const PlaneNormals source : {PlaneNormals::kModel, PlaneNormals::kScan}) {
      options.plane_normals = source;
      LinkState plane_state;
      plane_state.q = q_true + (revolute ? 4.0 * kDeg : 0.03);
      WeightedIcpSummary plane;
      ASSERT_TRUE(icp.Fit(s.samples, motion, options, &plane_state, &plane).ok());
      EXPECT_EQ(plane.stop_reason, IcpStopReason::kConverged) << plane.BriefReport();
      EXPECT_NEAR(plane_state.q, q_true, 1e-6);
      EXPECT_LE(plane.iterations, point.iterations)
          << "point-to-plane " << plane.BriefReport() << " vs " << point.BriefReport();
    }
  }
}

TEST(WeightedIcpTest, StopsWhenTheScanIsElsewhere) {
  const Synthetic s = MakeSynthetic(kTrueFreePose, 0.0);
  LinkState state;
  state.T_world_link = kTrueFreePose * PoseFromXyzRpy({1.0, 0.0, 0.0}, {0, 0, 0});
  const FitOutput out = RunFit(s, LinkMotion::Free(), KdTreeOptions(), state);
  EXPECT_EQ(out.summary.stop_reason, IcpStopReason::kTooFewCorrespondences);
  EXPECT_EQ(out.summary.inliers, 0u);
  EXPECT_EQ(out.summary.iterations, 0);
}

TEST(WeightedIcpTest, RejectsBadOptionsAndInputs) {
  const Synthetic s = MakeSynthetic(kTrueFreePose, 0.0);
  CorrespondenceSearch search(&s.scans, &s.weights);
  ResidualOptions bad_loss;
  bad_loss.loss = "l7";
  WeightedIcp bad_icp(&s.scans, &search, nullptr, bad_loss);
  LinkState state;
  WeightedIcpSummary summary;
  WeightedIcpOptions options = KdTreeOptions();
  Status status = bad_icp.Fit(s.samples, LinkMotion::Free(), options, &state, &summary);
  EXPECT_NE(status.message().find("unknown loss 'l7'"), std::string::npos) << status.message();
  WeightedIcp icp(&s.scans, &search);
  options = KdTreeOptions();
  options.max_iterations = 0;
  EXPECT_FALSE(icp.Fit(s.samples, LinkMotion::Free(), options, &state, &summary).ok());
  options = KdTreeOptions();
  EXPECT_FALSE(icp.Fit(SurfaceSamples(), LinkMotion::Free(), options, &state, &summary).ok());
  options.point_to_plane = true;
  options.plane_normals = PlaneNormals::kScan;  // no normals given to the engine
  status = icp.Fit(s.samples, LinkMotion::Free(), options, &state, &summary);
  EXPECT_NE(status.message().find("target normals"), std::string::npos) << status.message();
  options.plane_normals = PlaneNormals::kModel;
  SurfaceSamples bare = s.samples;
  bare.normals.clear();
  status = icp.Fit(bare, LinkMotion::Free(), options, &state, &summary);
  EXPECT_NE(status.message().find("sample normals"), std::string::npos) << status.message();
  JointParameterization parameterization;
  EXPECT_TRUE(ParseJointParameterization("pose_penalty", &parameterization).ok());
  EXPECT_EQ(parameterization, JointParameterization::kPoseWithPenalties);
  EXPECT_FALSE(ParseJointParameterization("euler", &parameterization).ok());
}

}  // namespace
}  // namespace edgefit
