// Data residual of the whole-chain refinement (--refine_chain): paper
// Eq. (8) for a CAD sample of any link, its pose a function of the base
// pose and every independent joint value at once:
//
//   point-to-plane   r = sqrt(w_edge) n_world^T (T_world_link(x) p_link - q_world)   1 residual [m]
//   point-to-point   r = sqrt(w_edge) (T_world_link(x) p_link - q_world)             3 residuals
//   [m]
//
//   x = (delta_base[6], q[n]):  T_world_base = (Exp(delta_rot) R_0, t_0 + delta_trans),
//   T_world_link(x) = T_world_base * ForwardKinematics(q with its mimic and
//   loop-closure joints resolved)
//
// The kinematic constraints are exact: the links can only move as the joints
// let them. The pose of a link and its derivatives d(R, t)/dx_k come from a
// LinkPoseSource (solvers/chain_kinematics.h), which evaluates the chain once
// per parameter vector for all residuals; the Jacobian of a residual is then
//   dr/dx_k = sqrt(w_edge) [n^T] (dR_k p_link + dt_k).
// n_world is fixed for the solve (the CAD sample's normal posed at the start
// of the ICP iteration, as in point_to_plane_cost.h).
//
// Parameter blocks: delta_base[6] (rotation vector [rad], translation [m]),
// and, when the model has independent joints, q[n] ([rad] or [m]).
#ifndef EDGEFIT_COSTS_CHAIN_POINT_COST_H_
#define EDGEFIT_COSTS_CHAIN_POINT_COST_H_

#include <ceres/cost_function.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace edgefit {

// A link's pose at a parameter vector and its partial derivatives.
struct LinkPoseJacobian {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  std::vector<Eigen::Matrix3d> dR;  // per parameter: 6 base, then the joints
  std::vector<Eigen::Vector3d> dt;
};

class LinkPoseSource {
 public:
  virtual ~LinkPoseSource() = default;
  // The pose of `link` at parameters (delta_base[6], q[num_joints]), with
  // its derivatives; valid until the next call with other parameters.
  virtual const LinkPoseJacobian& At(const double* delta_base, const double* q, int link) = 0;
  virtual int num_joints() const = 0;
};

class ChainPointCost final : public ceres::CostFunction {
 public:
  // n_world: unit plane normal, or nullptr for the point-to-point residual.
  ChainPointCost(LinkPoseSource* poses, int link, const Eigen::Vector3d& p_link,
                 const Eigen::Vector3d& q_world, const Eigen::Vector3d* n_world, double w_edge)
      : poses_(poses),
        link_(link),
        p_link_(p_link),
        q_world_(q_world),
        plane_(n_world != nullptr),
        n_world_(plane_ ? n_world->normalized() : Eigen::Vector3d::Zero()),
        sqrt_weight_(std::sqrt(w_edge)) {
    CHECK(poses != nullptr);
    CHECK_GE(w_edge, 0.0);
    set_num_residuals(plane_ ? 1 : 3);
    mutable_parameter_block_sizes()->push_back(6);
    if (poses->num_joints() > 0) mutable_parameter_block_sizes()->push_back(poses->num_joints());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int n = poses_->num_joints();
    const LinkPoseJacobian& pose =
        poses_->At(parameters[0], n > 0 ? parameters[1] : nullptr, link_);
    const Eigen::Vector3d d = sqrt_weight_ * (pose.R * p_link_ + pose.t - q_world_);
    if (plane_) {
      residuals[0] = n_world_.dot(d);
    } else {
      for (int r = 0; r < 3; ++r) residuals[r] = d[r];
    }
    if (jacobians == nullptr) return true;
    const int rows = plane_ ? 1 : 3;
    for (int block = 0; block < (n > 0 ? 2 : 1); ++block) {
      if (jacobians[block] == nullptr) continue;
      const int columns = block == 0 ? 6 : n;
      const int first = block == 0 ? 0 : 6;
      for (int k = 0; k < columns; ++k) {
        const size_t i = static_cast<size_t>(first + k);
        const Eigen::Vector3d dy = sqrt_weight_ * (pose.dR[i] * p_link_ + pose.dt[i]);
        if (plane_) {
          jacobians[block][k] = n_world_.dot(dy);
        } else {
          for (int r = 0; r < rows; ++r) jacobians[block][r * columns + k] = dy[r];
        }
      }
    }
    return true;
  }

 private:
  LinkPoseSource* poses_;  // borrowed
  const int link_;
  const Eigen::Vector3d p_link_;
  const Eigen::Vector3d q_world_;
  const bool plane_;
  const Eigen::Vector3d n_world_;
  const double sqrt_weight_;
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_CHAIN_POINT_COST_H_
