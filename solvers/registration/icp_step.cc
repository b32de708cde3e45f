#include "solvers/registration/icp_step.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <glog/logging.h>

#include <cmath>
#include <memory>

#include "costs/axis_point_cost.h"
#include "costs/joint_batch_cost.h"
#include "costs/joint_point_to_plane_cost.h"
#include "costs/point_to_line_cost.h"
#include "costs/point_to_plane_cost.h"
#include "costs/point_to_plane_penalty_cost.h"
#include "costs/point_to_point_cost.h"
#include "costs/prismatic_point_cost.h"
#include "costs/revolute_point_cost.h"
#include "solvers/registration/rotation_manifold.h"

namespace edgefit {

bool SolvesJointValue(const LinkMotion& motion, const ResidualOptions& residuals) {
  return motion.constrained() && residuals.parameterization == JointParameterization::kJointSpace;
}

namespace {

// Eq. (10): the axis points a, b of the child must stay where the parent
// puts them (a0 = T_world_joint a, b0 = T_world_joint b: a rotation about
// the axis leaves its points in place).
void AddRevolutePenalties(const IcpStepInput& input, double lambda, IcpParameters* parameters,
                          ceres::Problem* problem) {
  const LinkMotion& motion = *input.motion;
  for (const double side : {-1.0, 1.0}) {
    const Eigen::Vector3d a_link =
        input.axis_center_link + side * input.axis_half_span * motion.axis_joint;
    problem->AddResidualBlock(AxisPointCost::Create(a_link, motion.T_world_joint * a_link, lambda),
                              nullptr, parameters->rotation_world_link,
                              parameters->translation_world_link);
  }
}

// Eq. (14): the axis points a, b stay on the parent's joint line L; the
// off-axis point c stays on the plane P spanned by L and c's offset, which
// locks the rotation about the axis.
void AddPrismaticPenalties(const IcpStepInput& input, double lambda, IcpParameters* parameters,
                           ceres::Problem* problem) {
  const LinkMotion& motion = *input.motion;
  const Eigen::Vector3d& axis = motion.axis_joint;
  const Eigen::Vector3d l0_world = motion.T_world_joint.translation();
  const Eigen::Vector3d l_world = motion.T_world_joint.linear() * axis;
  for (const double side : {-1.0, 1.0}) {
    const Eigen::Vector3d a_link = input.axis_center_link + side * input.axis_half_span * axis;
    problem->AddResidualBlock(PointToLineCost::Create(a_link, l0_world, l_world, lambda), nullptr,
                              parameters->rotation_world_link, parameters->translation_world_link);
  }
  const Eigen::Vector3d u = axis.unitOrthogonal();
  const Eigen::Vector3d c_link = input.axis_center_link + input.axis_half_span * u;
  const Eigen::Vector3d n_world = motion.T_world_joint.linear() * axis.cross(u);
  problem->AddResidualBlock(
      PointToPlanePenaltyCost::Create(c_link, motion.T_world_joint * c_link, n_world, lambda),
      nullptr, parameters->rotation_world_link, parameters->translation_world_link);
}

}  // namespace

bool SolveIcpStep(const IcpStepInput& input, IcpParameters* parameters, double* final_cost) {
  CHECK(input.p_link != nullptr && input.correspondences != nullptr && input.scans != nullptr &&
        input.motion != nullptr && input.options != nullptr && input.residuals != nullptr &&
        input.loss != nullptr);
  const WeightedIcpOptions& options = *input.options;
  const LinkMotion& motion = *input.motion;
  const ResidualOptions& residuals = *input.residuals;
  const bool joint_space = SolvesJointValue(motion, residuals);

  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.disable_all_safety_checks = true;  // blocks are built right here
  ceres::Problem problem(problem_options);

  // Joint space under the trivial loss: every data residual in one block
  // (costs/joint_batch_cost.h); the same problem, solved without the set-up
  // of a block per correspondence.
  std::unique_ptr<JointBatchCost> batch;
  if (joint_space && residuals.loss == "trivial") {
    batch = std::make_unique<JointBatchCost>(motion.type == LinkMotion::Type::kRevolute
                                                 ? JointBatchCost::Motion::kRevolute
                                                 : JointBatchCost::Motion::kPrismatic,
                                             motion.T_world_joint, motion.axis_joint);
  }
  double total_weight = 0.0;
  for (const Correspondence& m : *input.correspondences) {
    const OrganizedScan& scan = input.scans->scans[static_cast<size_t>(m.scan)];
    const size_t cell = static_cast<size_t>(m.cell);
    const Eigen::Vector3d p_link = (*input.p_link)[static_cast<size_t>(m.source)].cast<double>();
    const Eigen::Vector3d q_world = scan.PointWorld(cell);
    const double w_edge = static_cast<double>(m.weight);
    total_weight += w_edge;
    // The plane's normal (point_to_plane): the sample's (PlaneNormals::kModel)
    // or the target's, when the edge stage has one.
    bool has_normal = false;
    Eigen::Vector3d n_world;
    if (options.point_to_plane && input.n_link != nullptr) {
      has_normal = true;
      n_world = input.R_world_link * (*input.n_link)[static_cast<size_t>(m.source)].cast<double>();
    } else if (options.point_to_plane) {
      const Eigen::Vector3f& n_scanner =
          (*input.normals_scanner)[static_cast<size_t>(m.scan)][cell];
      has_normal = !std::isnan(n_scanner.x());
      if (has_normal) n_world = scan.T_world_scanner().linear() * n_scanner.cast<double>();
    }
    if (batch != nullptr) {
      if (has_normal) {
        batch->AddPlane(p_link, q_world, n_world, w_edge);
      } else {
        batch->AddPoint(p_link, q_world, w_edge);
      }
      continue;
    }
    if (joint_space) {
      ceres::CostFunction* cost = nullptr;
      if (motion.type == LinkMotion::Type::kRevolute) {
        const RevolutePointCost point(motion.T_world_joint, Pose::Identity(), motion.axis_joint,
                                      p_link, q_world, w_edge);
        cost = has_normal ? JointPointToPlaneCost<RevolutePointCost>::Create(point, n_world)
                          : new ceres::AutoDiffCostFunction<RevolutePointCost, 3, 1>(
                                new RevolutePointCost(point));
      } else {
        const PrismaticPointCost point(motion.T_world_joint, Pose::Identity(), motion.axis_joint,
                                       p_link, q_world, w_edge);
        cost = has_normal ? JointPointToPlaneCost<PrismaticPointCost>::Create(point, n_world)
                          : new ceres::AutoDiffCostFunction<PrismaticPointCost, 3, 1>(
                                new PrismaticPointCost(point));
      }
      problem.AddResidualBlock(cost, input.loss, &parameters->q);
      continue;
    }
    ceres::CostFunction* cost =
        has_normal ? PointToPlaneCost::Create(p_link, q_world, n_world, w_edge) : nullptr;
    if (cost == nullptr) cost = PointToPointCost::Create(p_link, q_world, w_edge);
    problem.AddResidualBlock(cost, input.loss, parameters->rotation_world_link,
                             parameters->translation_world_link);
  }

  if (batch != nullptr && batch->num_residuals() > 0) {
    problem.AddResidualBlock(batch.release(), nullptr, &parameters->q);
  }
  if (joint_space) {
    if (motion.has_limits) {
      problem.SetParameterLowerBound(&parameters->q, 0, motion.lower);
      problem.SetParameterUpperBound(&parameters->q, 0, motion.upper);
    }
  } else {
    problem.SetManifold(parameters->rotation_world_link, NewAngleAxisManifold());
    // lambda relative to the data weight (WeightedIcpOptions::lambda).
    const double penalty_weight = residuals.lambda * total_weight;
    if (motion.type == LinkMotion::Type::kRevolute) {
      AddRevolutePenalties(input, penalty_weight, parameters, &problem);
    } else if (motion.type == LinkMotion::Type::kPrismatic) {
      AddPrismaticPenalties(input, penalty_weight, parameters, &problem);
    }
  }

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_QR;
  solver_options.max_num_iterations = options.solver_iterations;
  solver_options.num_threads = 1;  // deterministic sums (weighted_icp.h)
  solver_options.function_tolerance = 1e-14;
  solver_options.gradient_tolerance = 1e-16;
  solver_options.parameter_tolerance = 1e-14;
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return false;
  *final_cost = summary.final_cost;
  return true;
}

}  // namespace edgefit
