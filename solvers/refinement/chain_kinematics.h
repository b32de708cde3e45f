// The poses of every link of a KinematicModel as a function of the base
// pose and the independent joint values, with their partial derivatives:
// the LinkPoseSource of the whole-chain refinement (costs/chain_point_cost.h).
//
// Parameters x = (delta_base[6], q[n]) about an anchor base pose T_0:
//   T_world_base(delta) = (Exp(delta_rot) R_0, t_0 + delta_trans)
// (the rotation perturbed on the left, in the world frame), q the model's
// IndependentJoints() in that order; mimic and loop-closure joints follow
// them (KinematicModel::ResolveDependentJoints). The derivatives are central
// differences of the forward kinematics (step 1e-6 rad or m: their error is
// O(1e-12), far below what a solve needs; the loop closures are solved to
// 1e-13 m). The chain is evaluated once per new parameter point, in
// PrepareForEvaluation (the problem's ceres::EvaluationCallback), and read
// by every residual block of the solve.
#ifndef EDGEFIT_SOLVERS_REFINEMENT_CHAIN_KINEMATICS_H_
#define EDGEFIT_SOLVERS_REFINEMENT_CHAIN_KINEMATICS_H_

#include <ceres/evaluation_callback.h>

#include <vector>

#include "costs/chain_point_cost.h"
#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

class ChainKinematics final : public LinkPoseSource, public ceres::EvaluationCallback {
 public:
  // model: borrowed. q_full: every joint (model order), the values of the
  // dependent ones warm-start their solves. delta_base (6 values) and q (one
  // per independent joint) are the problem's parameter blocks, borrowed:
  // PrepareForEvaluation poses the chain at the values they hold.
  ChainKinematics(const KinematicModel* model, const Pose& T_world_base_anchor,
                  const std::vector<double>& q_full, const double* delta_base, const double* q);

  // ceres::EvaluationCallback: the link poses and their derivatives at the
  // parameter blocks' values, computed once for every residual block.
  void PrepareForEvaluation(bool evaluate_jacobians, bool new_evaluation_point) override;

  const LinkPoseJacobian& At(int link) const override;
  int num_joints() const override { return static_cast<int>(independent_.size()); }

  // The model's independent joints (indices into joints()), in parameter order.
  const std::vector<int>& independent_joints() const { return independent_; }
  // The base pose at delta_base and every joint's value at q (dependent ones resolved).
  Pose BasePose(const double* delta_base) const;
  std::vector<double> FullJoints(const double* q);

 private:
  // T_world_link of every link at (delta_base, q).
  std::vector<Pose> Links(const double* delta_base, const double* q);

  const KinematicModel* model_;
  const Pose T_world_base_anchor_;
  const double* delta_base_;    // parameter block, borrowed
  const double* q_;             // parameter block, borrowed
  std::vector<double> q_full_;  // the last resolved values (warm start)
  std::vector<int> independent_;
  std::vector<double> key_;  // the parameters links_ holds, NaN: none
  std::vector<LinkPoseJacobian> links_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REFINEMENT_CHAIN_KINEMATICS_H_
