// How the precise registration stages form their data residuals: the
// robust loss, and how a link is held on its joint. One per fit
// (FitOptions::residuals): the base ICP, the joint and subtree ICPs and the
// whole-chain refinement all use it; WeightedIcp and RefineChain take it
// when they are made or called, never per stage.
#ifndef EDGEFIT_SOLVERS_REGISTRATION_RESIDUAL_OPTIONS_H_
#define EDGEFIT_SOLVERS_REGISTRATION_RESIDUAL_OPTIONS_H_

#include <string>

#include "edgefit/core/status.h"

namespace edgefit {

// The constraint of a link on a joint (LinkMotion) in the ICP:
//   kJointSpace         the joint value is the only parameter
//                       (costs/revolute_point_cost.h, prismatic_point_cost.h):
//                       the link never leaves its joint;
//   kPoseWithPenalties  the paper's: a 6-DoF pose (angle-axis on the
//                       rotation_manifold.h manifold + translation) with the
//                       Eq. (10) axis-point penalties (revolute) or the
//                       Eq. (14) line and plane penalties (prismatic), then
//                       the projection onto the joint (LinkMotion::Project).
// BENCHMARK.md ("ICP engine") compares them; the default is the better one.
enum class JointParameterization { kJointSpace, kPoseWithPenalties };

// "joint_space" / "pose_penalty".
const char* JointParameterizationName(JointParameterization parameterization);
Status ParseJointParameterization(const std::string& name, JointParameterization* out);

struct ResidualOptions {
  // Loss of the data residuals by name (costs/robust_loss.h: trivial, huber,
  // cauchy, soft_l1, arctan, tukey) and its scale in residual units
  // (metres for w_edge = 1; a residual carries sqrt(w_edge) |R p + t - q|).
  std::string loss = "trivial";
  double loss_scale = 0.005;  // [m]
  JointParameterization parameterization = JointParameterization::kJointSpace;
  // kPoseWithPenalties: weight of the Eq. (10) / (14) penalties relative to
  // the data: each penalty residual is scaled by sqrt(lambda * W), W the sum
  // of the data weights of the iteration, so lambda = 1 makes a shift of the
  // axis cost as much as the same shift of every sample, for any sample
  // count (dimensionless).
  double lambda = 1.0;

  bool IsValid(std::string* error) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_RESIDUAL_OPTIONS_H_
