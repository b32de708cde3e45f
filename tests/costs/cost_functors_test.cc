// Every cost functor in costs/: autodiff Jacobians against Ridders numeric
// differentiation at seeded random poses/points (the analytic JointBatchCost
// against the autodiff functors it batches), hand-computed residuals (zero
// at the true pose, sqrt(weight) scaling), and small end-to-end solves.
#include <ceres/ceres.h>
#include <ceres/numeric_diff_cost_function.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "costs/axis_point_cost.h"
#include "costs/joint_batch_cost.h"
#include "costs/joint_point_to_plane_cost.h"
#include "costs/point_to_line_cost.h"
#include "costs/point_to_plane_cost.h"
#include "costs/point_to_plane_penalty_cost.h"
#include "costs/point_to_point_cost.h"
#include "costs/prismatic_point_cost.h"
#include "costs/revolute_point_cost.h"
#include "edgefit/core/angles.h"

namespace edgefit {
namespace {

using Eigen::Vector3d;

Vector3d RandomVector(std::mt19937& rng, double range) {
  std::uniform_real_distribution<double> u(-range, range);
  return Vector3d(u(rng), u(rng), u(rng));
}

Eigen::Isometry3d RandomPose(std::mt19937& rng) {
  const Vector3d w = RandomVector(rng, 2.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
  T.translation() = RandomVector(rng, 2.0);
  return T;
}

// Residuals and Jacobians of one cost function at the given parameter values.
struct Evaluation {
  std::vector<double> residuals;
  std::vector<std::vector<double>> jacobians;  // row-major, one per block
};

Evaluation Evaluate(const ceres::CostFunction& cost, std::vector<std::vector<double>>& params) {
  Evaluation e;
  e.residuals.resize(cost.num_residuals());
  std::vector<double*> param_ptrs;
  std::vector<double*> jacobian_ptrs;
  for (size_t i = 0; i < params.size(); ++i) {
    param_ptrs.push_back(params[i].data());
    e.jacobians.emplace_back(cost.num_residuals() * cost.parameter_block_sizes()[i]);
  }
  for (auto& j : e.jacobians) jacobian_ptrs.push_back(j.data());
  EXPECT_TRUE(cost.Evaluate(param_ptrs.data(), e.residuals.data(), jacobian_ptrs.data()));
  return e;
}

// One functor, built twice from the same random data: through Create()
// (autodiff) and as a ceres::NumericDiffCostFunction (Ridders).
struct Instance {
  std::unique_ptr<ceres::CostFunction> autodiff;
  std::unique_ptr<ceres::CostFunction> numeric;
  std::vector<std::vector<double>> params;
};

template <typename F, int kResiduals, int... kBlocks>
std::unique_ptr<ceres::CostFunction> Numeric(F* functor) {
  return std::make_unique<
      ceres::NumericDiffCostFunction<F, ceres::RIDDERS, kResiduals, kBlocks...>>(functor);
}

std::vector<std::vector<double>> RandomPoseParams(std::mt19937& rng) {
  const Vector3d w = RandomVector(rng, 2.0);
  const Vector3d t = RandomVector(rng, 2.0);
  return {{w.x(), w.y(), w.z()}, {t.x(), t.y(), t.z()}};
}

struct FunctorCase {
  std::string name;
  std::function<Instance(std::mt19937&)> make;
};

std::vector<FunctorCase> AllFunctors() {
  std::uniform_real_distribution<double> weight(0.1, 10.0);
  return {
      {"PointToPoint",
       [weight](std::mt19937& rng) mutable {
         const Vector3d p = RandomVector(rng, 1.0), q = RandomVector(rng, 3.0);
         const double w = weight(rng);
         return Instance{std::unique_ptr<ceres::CostFunction>(PointToPointCost::Create(p, q, w)),
                         Numeric<PointToPointCost, 3, 3, 3>(new PointToPointCost(p, q, w)),
                         RandomPoseParams(rng)};
       }},
      {"PointToPlane",
       [weight](std::mt19937& rng) mutable {
         const Vector3d p = RandomVector(rng, 1.0), q = RandomVector(rng, 3.0);
         const Vector3d n = RandomVector(rng, 1.0);
         const double w = weight(rng);
         return Instance{std::unique_ptr<ceres::CostFunction>(PointToPlaneCost::Create(p, q, n, w)),
                         Numeric<PointToPlaneCost, 1, 3, 3>(new PointToPlaneCost(p, q, n, w)),
                         RandomPoseParams(rng)};
       }},
      {"AxisPoint",
       [weight](std::mt19937& rng) mutable {
         const Vector3d a = RandomVector(rng, 1.0), a0 = RandomVector(rng, 3.0);
         const double lambda = weight(rng);
         return Instance{std::unique_ptr<ceres::CostFunction>(AxisPointCost::Create(a, a0, lambda)),
                         Numeric<AxisPointCost, 3, 3, 3>(new AxisPointCost(a, a0, lambda)),
                         RandomPoseParams(rng)};
       }},
      {"PointToLine",
       [weight](std::mt19937& rng) mutable {
         const Vector3d a = RandomVector(rng, 1.0), l0 = RandomVector(rng, 3.0);
         const Vector3d l = RandomVector(rng, 1.0);
         const double lambda = weight(rng);
         return Instance{
             std::unique_ptr<ceres::CostFunction>(PointToLineCost::Create(a, l0, l, lambda)),
             Numeric<PointToLineCost, 3, 3, 3>(new PointToLineCost(a, l0, l, lambda)),
             RandomPoseParams(rng)};
       }},
      {"PointToPlanePenalty",
       [weight](std::mt19937& rng) mutable {
         const Vector3d c = RandomVector(rng, 1.0), c0 = RandomVector(rng, 3.0);
         const Vector3d n = RandomVector(rng, 1.0);
         const double lambda = weight(rng);
         return Instance{std::unique_ptr<ceres::CostFunction>(
                             PointToPlanePenaltyCost::Create(c, c0, n, lambda)),
                         Numeric<PointToPlanePenaltyCost, 1, 3, 3>(
                             new PointToPlanePenaltyCost(c, c0, n, lambda)),
                         RandomPoseParams(rng)};
       }},
      {"RevolutePoint",
       [weight](std::mt19937& rng) mutable {
         const Eigen::Isometry3d T_wp = RandomPose(rng), T_pj = RandomPose(rng);
         const Vector3d axis = RandomVector(rng, 1.0), p = RandomVector(rng, 1.0);
         const Vector3d q = RandomVector(rng, 3.0);
         const double w = weight(rng);
         const double theta = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
         return Instance{
             std::unique_ptr<ceres::CostFunction>(
                 RevolutePointCost::Create(T_wp, T_pj, axis, p, q, w)),
             Numeric<RevolutePointCost, 3, 1>(new RevolutePointCost(T_wp, T_pj, axis, p, q, w)),
             {{theta}}};
       }},
      {"PrismaticPoint",
       [weight](std::mt19937& rng) mutable {
         const Eigen::Isometry3d T_wp = RandomPose(rng), T_pj = RandomPose(rng);
         const Vector3d axis = RandomVector(rng, 1.0), p = RandomVector(rng, 1.0);
         const Vector3d q = RandomVector(rng, 3.0);
         const double w = weight(rng);
         const double d = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
         return Instance{
             std::unique_ptr<ceres::CostFunction>(
                 PrismaticPointCost::Create(T_wp, T_pj, axis, p, q, w)),
             Numeric<PrismaticPointCost, 3, 1>(new PrismaticPointCost(T_wp, T_pj, axis, p, q, w)),
             {{d}}};
       }},
      {"RevolutePointToPlane",
       [weight](std::mt19937& rng) mutable {
         const Eigen::Isometry3d T_wp = RandomPose(rng), T_pj = RandomPose(rng);
         const Vector3d axis = RandomVector(rng, 1.0), p = RandomVector(rng, 1.0);
         const Vector3d q = RandomVector(rng, 3.0), n = RandomVector(rng, 1.0);
         const RevolutePointCost point(T_wp, T_pj, axis, p, q, weight(rng));
         using Cost = JointPointToPlaneCost<RevolutePointCost>;
         return Instance{std::unique_ptr<ceres::CostFunction>(Cost::Create(point, n)),
                         Numeric<Cost, 1, 1>(new Cost(point, n)),
                         {{std::uniform_real_distribution<double>(-kPi, kPi)(rng)}}};
       }},
      {"PrismaticPointToPlane",
       [weight](std::mt19937& rng) mutable {
         const Eigen::Isometry3d T_wp = RandomPose(rng), T_pj = RandomPose(rng);
         const Vector3d axis = RandomVector(rng, 1.0), p = RandomVector(rng, 1.0);
         const Vector3d q = RandomVector(rng, 3.0), n = RandomVector(rng, 1.0);
         const PrismaticPointCost point(T_wp, T_pj, axis, p, q, weight(rng));
         using Cost = JointPointToPlaneCost<PrismaticPointCost>;
         return Instance{std::unique_ptr<ceres::CostFunction>(Cost::Create(point, n)),
                         Numeric<Cost, 1, 1>(new Cost(point, n)),
                         {{std::uniform_real_distribution<double>(-1.0, 1.0)(rng)}}};
       }},
  };
}

class CostJacobianTest : public testing::TestWithParam<FunctorCase> {};

TEST_P(CostJacobianTest, AutodiffMatchesNumericDiff) {
  std::mt19937 rng(20240611);
  for (int trial = 0; trial < 20; ++trial) {
    Instance instance = GetParam().make(rng);
    ASSERT_EQ(instance.autodiff->num_residuals(), instance.numeric->num_residuals());
    ASSERT_EQ(instance.autodiff->parameter_block_sizes(),
              instance.numeric->parameter_block_sizes());
    const Evaluation ad = Evaluate(*instance.autodiff, instance.params);
    const Evaluation nd = Evaluate(*instance.numeric, instance.params);
    for (size_t i = 0; i < ad.residuals.size(); ++i) {
      EXPECT_NEAR(ad.residuals[i], nd.residuals[i], 1e-12) << "trial " << trial;
    }
    for (size_t b = 0; b < ad.jacobians.size(); ++b) {
      double norm2 = 0.0;
      for (double v : ad.jacobians[b]) norm2 += v * v;
      EXPECT_GT(norm2, 1e-12) << "trial " << trial << " block " << b << ": Jacobian is zero";
      for (size_t k = 0; k < ad.jacobians[b].size(); ++k) {
        const double scale = std::max(1.0, std::abs(ad.jacobians[b][k]));
        EXPECT_NEAR(ad.jacobians[b][k], nd.jacobians[b][k], 1e-8 * scale)
            << "trial " << trial << " block " << b << " entry " << k;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFunctors, CostJacobianTest, testing::ValuesIn(AllFunctors()),
                         [](const testing::TestParamInfo<FunctorCase>& info) {
                           return info.param.name;
                         });

// ---- Hand-computed residuals ------------------------------------------------
// Pose used below: R = Rz(90 deg), t = (1, 2, 3); p = (1, 0, 0) maps to
// R p + t = (0, 1, 0) + (1, 2, 3) = (1, 3, 3).
std::vector<std::vector<double>> Rz90Pose() { return {{0.0, 0.0, kPi / 2}, {1.0, 2.0, 3.0}}; }

std::vector<double> Residuals(ceres::CostFunction* raw, std::vector<std::vector<double>> params) {
  std::unique_ptr<ceres::CostFunction> cost(raw);
  std::vector<double*> ptrs;
  for (auto& p : params) ptrs.push_back(p.data());
  std::vector<double> r(cost->num_residuals());
  EXPECT_TRUE(cost->Evaluate(ptrs.data(), r.data(), nullptr));
  return r;
}

void ExpectVectorNear(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], 1e-12) << i;
}

const Vector3d kP(1.0, 0.0, 0.0);
const Vector3d kPWorld(1.0, 3.0, 3.0);

TEST(CostResidualTest, PointToPoint) {
  // sqrt(4) * ((1, 3, 3) - 0).
  ExpectVectorNear(Residuals(PointToPointCost::Create(kP, Vector3d::Zero(), 4.0), Rz90Pose()),
                   {2.0, 6.0, 6.0});
  ExpectVectorNear(Residuals(PointToPointCost::Create(kP, kPWorld, 4.0), Rz90Pose()),
                   {0.0, 0.0, 0.0});
  ExpectVectorNear(Residuals(PointToPointCost::Create(kP, kPWorld, 0.0), {{0, 0, 0}, {0, 0, 0}}),
                   {0.0, 0.0, 0.0});
}

TEST(CostResidualTest, PointToPlane) {
  // n = (0, 0, 1) after normalisation: sqrt(4) * 3.
  ExpectVectorNear(
      Residuals(PointToPlaneCost::Create(kP, Vector3d::Zero(), Vector3d(0, 0, 2), 4.0), Rz90Pose()),
      {6.0});
  // In-plane offset (x, y) does not count.
  ExpectVectorNear(
      Residuals(PointToPlaneCost::Create(kP, Vector3d(5, -7, 3), Vector3d(0, 0, 2), 4.0),
                Rz90Pose()),
      {0.0});
}

TEST(CostResidualTest, AxisPoint) {
  // sqrt(9) * ((1, 3, 3) - (1, 3, 0)).
  ExpectVectorNear(Residuals(AxisPointCost::Create(kP, Vector3d(1, 3, 0), 9.0), Rz90Pose()),
                   {0.0, 0.0, 9.0});
  ExpectVectorNear(Residuals(AxisPointCost::Create(kP, kPWorld, 9.0), Rz90Pose()), {0.0, 0.0, 0.0});
}

TEST(CostResidualTest, PointToLine) {
  // Line through the origin along z: orthogonal part of (1, 3, 3) is (1, 3, 0).
  ExpectVectorNear(
      Residuals(PointToLineCost::Create(kP, Vector3d::Zero(), Vector3d(0, 0, 5), 4.0), Rz90Pose()),
      {2.0, 6.0, 0.0});
  // Any point on the line gives zero, wherever along the line.
  ExpectVectorNear(
      Residuals(PointToLineCost::Create(kP, Vector3d(1, 3, -8), Vector3d(0, 0, -1), 4.0),
                Rz90Pose()),
      {0.0, 0.0, 0.0});
}

TEST(CostResidualTest, PointToPlanePenalty) {
  // Plane y = 0: signed distance 3, times sqrt(4).
  ExpectVectorNear(
      Residuals(PointToPlanePenaltyCost::Create(kP, Vector3d(4, 0, 9), Vector3d(0, 3, 0), 4.0),
                Rz90Pose()),
      {6.0});
  ExpectVectorNear(
      Residuals(PointToPlanePenaltyCost::Create(kP, Vector3d(4, 3, 9), Vector3d(0, 3, 0), 4.0),
                Rz90Pose()),
      {0.0});
}

// T_world_parent = Trans(1, 0, 0) Rz(90 deg), T_parent_joint = Trans(0, 0, 1).
Eigen::Isometry3d HandWorldParent() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Vector3d(1, 0, 0)).rotate(Eigen::AngleAxisd(kPi / 2, Vector3d::UnitZ()));
  return T;
}
Eigen::Isometry3d HandParentJoint() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translate(Vector3d(0, 0, 1));
  return T;
}

TEST(CostResidualTest, RevolutePoint) {
  // Rot(z, 90 deg) (1, 0, 0) = (0, 1, 0); + (0, 0, 1) = (0, 1, 1);
  // Rz(90 deg) -> (-1, 0, 1); + (1, 0, 0) = (0, 0, 1).
  ExpectVectorNear(
      Residuals(RevolutePointCost::Create(HandWorldParent(), HandParentJoint(), Vector3d(0, 0, 3),
                                          kP, Vector3d::Zero(), 4.0),
                {{kPi / 2}}),
      {0.0, 0.0, 2.0});
  ExpectVectorNear(
      Residuals(RevolutePointCost::Create(HandWorldParent(), HandParentJoint(), Vector3d(0, 0, 3),
                                          kP, Vector3d(0, 0, 1), 4.0),
                {{kPi / 2}}),
      {0.0, 0.0, 0.0});
}

TEST(CostResidualTest, PrismaticPoint) {
  // (1, 0, 0) + 2 * x = (3, 0, 0); + (0, 0, 1) = (3, 0, 1);
  // Rz(90 deg) -> (0, 3, 1); + (1, 0, 0) = (1, 3, 1).
  ExpectVectorNear(
      Residuals(PrismaticPointCost::Create(HandWorldParent(), HandParentJoint(), Vector3d(5, 0, 0),
                                           kP, Vector3d::Zero(), 4.0),
                {{2.0}}),
      {2.0, 6.0, 2.0});
  ExpectVectorNear(
      Residuals(PrismaticPointCost::Create(HandWorldParent(), HandParentJoint(), Vector3d(5, 0, 0),
                                           kP, Vector3d(1, 3, 1), 4.0),
                {{2.0}}),
      {0.0, 0.0, 0.0});
}

// JointBatchCost holds the per-correspondence joint-space residuals in one
// block: its residuals and analytic Jacobian equal, row for row, those of
// the autodiff functors it stands for (themselves checked against numeric
// differentiation above).
TEST(JointBatchCostTest, EqualsThePerCorrespondenceFunctors) {
  std::mt19937 rng(17);
  for (const bool revolute : {true, false}) {
    const Eigen::Isometry3d T_world_joint = RandomPose(rng);
    const Vector3d axis = RandomVector(rng, 1.0);
    JointBatchCost batch(
        revolute ? JointBatchCost::Motion::kRevolute : JointBatchCost::Motion::kPrismatic,
        T_world_joint, axis);
    std::vector<std::unique_ptr<ceres::CostFunction>> singles;
    for (int i = 0; i < 6; ++i) {
      const Vector3d p = RandomVector(rng, 0.5), q = RandomVector(rng, 2.0);
      const Vector3d n = RandomVector(rng, 1.0);
      const double w = i % 3 == 0 ? 10.0 : 1.0;
      const bool plane = i % 2 == 1;
      std::unique_ptr<ceres::CostFunction> single;
      if (revolute) {
        const RevolutePointCost point(T_world_joint, Eigen::Isometry3d::Identity(), axis, p, q, w);
        single.reset(plane ? JointPointToPlaneCost<RevolutePointCost>::Create(point, n)
                           : new ceres::AutoDiffCostFunction<RevolutePointCost, 3, 1>(
                                 new RevolutePointCost(point)));
      } else {
        const PrismaticPointCost point(T_world_joint, Eigen::Isometry3d::Identity(), axis, p, q, w);
        single.reset(plane ? JointPointToPlaneCost<PrismaticPointCost>::Create(point, n)
                           : new ceres::AutoDiffCostFunction<PrismaticPointCost, 3, 1>(
                                 new PrismaticPointCost(point)));
      }
      if (plane) {
        batch.AddPlane(p, q, n, w);
      } else {
        batch.AddPoint(p, q, w);
      }
      singles.push_back(std::move(single));
    }
    ASSERT_EQ(batch.num_residuals(), 3 * 3 + 3 * 1);
    std::vector<std::vector<double>> params = {{revolute ? 0.7 : 0.13}};
    const Evaluation all = Evaluate(batch, params);
    size_t row = 0;
    for (const auto& single : singles) {
      const Evaluation one = Evaluate(*single, params);
      for (size_t k = 0; k < one.residuals.size(); ++k, ++row) {
        EXPECT_NEAR(all.residuals[row], one.residuals[k], 1e-12) << "row " << row;
        EXPECT_NEAR(all.jacobians[0][row], one.jacobians[0][k], 1e-12) << "row " << row;
      }
    }
  }
}

// ---- End-to-end solves ------------------------------------------------------

ceres::Solver::Options TightOptions() {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  options.logging_type = ceres::SILENT;
  return options;
}

TEST(CostSolveTest, PointToPointRecoversSixDofTransform) {
  std::mt19937 rng(7);
  const Vector3d w_true(0.3, -0.2, 0.5);
  const Vector3d t_true(1.0, -2.0, 0.5);
  const Eigen::Matrix3d R_true =
      Eigen::AngleAxisd(w_true.norm(), w_true.normalized()).toRotationMatrix();
  std::uniform_real_distribution<double> weight(0.5, 10.0);

  double rotation[3] = {0.0, 0.0, 0.0};
  double translation[3] = {0.0, 0.0, 0.0};
  ceres::Problem problem;
  for (int i = 0; i < 50; ++i) {
    const Vector3d p_link = RandomVector(rng, 1.0);
    const Vector3d q_world = R_true * p_link + t_true;
    problem.AddResidualBlock(PointToPointCost::Create(p_link, q_world, weight(rng)), nullptr,
                             rotation, translation);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(rotation[k], w_true[k], 1e-9);
    EXPECT_NEAR(translation[k], t_true[k], 1e-9);
  }
}

TEST(CostSolveTest, RevolutePointRecoversJointAngle) {
  std::mt19937 rng(11);
  const Eigen::Isometry3d T_world_parent = RandomPose(rng);
  const Eigen::Isometry3d T_parent_joint = RandomPose(rng);
  const Vector3d axis = Vector3d(0.2, -0.4, 1.0).normalized();
  const double theta_true = 0.7;  // [rad]
  const Eigen::Isometry3d T_world_child =
      T_world_parent * T_parent_joint * Eigen::AngleAxisd(theta_true, axis);

  double theta = 0.0;
  ceres::Problem problem;
  for (int i = 0; i < 50; ++i) {
    const Vector3d p_child = RandomVector(rng, 1.0);
    problem.AddResidualBlock(RevolutePointCost::Create(T_world_parent, T_parent_joint, axis,
                                                       p_child, T_world_child * p_child, 2.0),
                             nullptr, &theta);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_NEAR(theta, theta_true, 1e-9);
}

TEST(CostSolveTest, PrismaticPointRecoversDisplacement) {
  std::mt19937 rng(13);
  const Eigen::Isometry3d T_world_parent = RandomPose(rng);
  const Eigen::Isometry3d T_parent_joint = RandomPose(rng);
  const Vector3d axis(1.0, 0.0, 0.0);
  const double d_true = 0.35;  // [m]
  const Eigen::Isometry3d T_world_child =
      T_world_parent * T_parent_joint * Eigen::Translation3d(d_true * axis);

  double d = 0.0;
  ceres::Problem problem;
  for (int i = 0; i < 20; ++i) {
    const Vector3d p_child = RandomVector(rng, 1.0);
    problem.AddResidualBlock(PrismaticPointCost::Create(T_world_parent, T_parent_joint, axis,
                                                        p_child, T_world_child * p_child, 1.0),
                             nullptr, &d);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_NEAR(d, d_true, 1e-9);
}

// Eq. (10): with the data term alone pulling the child off the joint, the
// axis-point penalties with a large lambda keep a and b on a0 and b0.
TEST(CostSolveTest, AxisPointPenaltyHoldsTheJoint) {
  const Vector3d a_link(0, 0, 0), b_link(0, 0, 1);  // joint axis = link z
  double rotation[3] = {0.0, 0.0, 0.0};
  double translation[3] = {0.0, 0.0, 0.0};
  ceres::Problem problem;
  // A data term that wants the link shifted by +0.1 m in x.
  problem.AddResidualBlock(PointToPointCost::Create(Vector3d(1, 0, 0), Vector3d(1.1, 0, 0), 1.0),
                           nullptr, rotation, translation);
  problem.AddResidualBlock(AxisPointCost::Create(a_link, a_link, 1e6), nullptr, rotation,
                           translation);
  problem.AddResidualBlock(AxisPointCost::Create(b_link, b_link, 1e6), nullptr, rotation,
                           translation);
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(translation[k], 0.0, 1e-6);
  EXPECT_NEAR(rotation[0], 0.0, 1e-6);
  EXPECT_NEAR(rotation[1], 0.0, 1e-6);
}

// Eq. (14): a and b on the parent's line (world x axis) and c on the plane
// z = 0 leave only the translation along x free, so a data term pulling the
// link by (0.3, 0.2, 0.1) moves it by (0.3, 0, 0) only.
TEST(CostSolveTest, PrismaticPenaltiesLeaveOnlyTheAxialDof) {
  const Vector3d a_link(0, 0, 0), b_link(1, 0, 0), c_link(0, 1, 0);
  const Vector3d p_link(0.5, 0.5, 0.5);
  double rotation[3] = {0.0, 0.0, 0.0};
  double translation[3] = {0.0, 0.0, 0.0};
  const double lambda = 1e8;
  ceres::Problem problem;
  problem.AddResidualBlock(PointToPointCost::Create(p_link, p_link + Vector3d(0.3, 0.2, 0.1), 1.0),
                           nullptr, rotation, translation);
  for (const Vector3d& axis_point : {a_link, b_link}) {
    problem.AddResidualBlock(
        PointToLineCost::Create(axis_point, Vector3d(-4, 0, 0), Vector3d(2, 0, 0), lambda), nullptr,
        rotation, translation);
  }
  problem.AddResidualBlock(
      PointToPlanePenaltyCost::Create(c_link, Vector3d(7, -3, 0), Vector3d(0, 0, 1), lambda),
      nullptr, rotation, translation);
  ceres::Solver::Summary summary;
  ceres::Solve(TightOptions(), &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_NEAR(translation[0], 0.3, 1e-6);
  EXPECT_NEAR(translation[1], 0.0, 1e-6);
  EXPECT_NEAR(translation[2], 0.0, 1e-6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rotation[k], 0.0, 1e-6);
}

}  // namespace
}  // namespace edgefit
