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
// LinkPoseSource (solvers/refinement/chain_kinematics.h), which evaluates the chain once
// per parameter vector for all residuals; the Jacobian of a residual is then
//   dr/dx_k = sqrt(w_edge) [n^T] (dR_k p_link + dt_k).
// n_world is fixed for the solve (the CAD sample's normal posed at the start
// of the ICP iteration, as in point_to_plane_cost.h).
//
// Residuals: one per sample (plane) or three (point); a block may hold
// several samples of one link (ChainPointCost). Parameter blocks:
// delta_base[6] (rotation vector [rad], translation [m]), and, when the
// model has independent joints, q[n] ([rad] or [m]).
#ifndef EDGEFIT_COSTS_CHAIN_POINT_COST_H_
#define EDGEFIT_COSTS_CHAIN_POINT_COST_H_

#include <ceres/cost_function.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>
#include <utility>
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
  // The pose of `link` at the problem's current parameters (delta_base[6],
  // q[num_joints]), with its derivatives: computed once per evaluation
  // point, before the residual blocks are evaluated (a
  // ceres::EvaluationCallback of the problem, chain_kinematics.h).
  virtual const LinkPoseJacobian& At(int link) const = 0;
  virtual int num_joints() const = 0;
};

// One sample's data: p_link (link frame), its scan point q_world, the
// plane normal n_world (unit; zero for the point-to-point residual) and
// w_edge.
struct ChainPoint {
  Eigen::Vector3d p_link = Eigen::Vector3d::Zero();
  Eigen::Vector3d q_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d n_world = Eigen::Vector3d::Zero();
  double w_edge = 1.0;
};

// The residuals of one or more samples of one link, all point-to-plane or
// all point-to-point. Under the trivial loss, samples of a link share one
// block (the sum of squares is the same, Ceres' per-block overhead is
// not); a robust loss needs one sample per block.
class ChainPointCost final : public ceres::CostFunction {
 public:
  ChainPointCost(const LinkPoseSource* poses, int link, bool plane, std::vector<ChainPoint> points)
      : poses_(poses), link_(link), plane_(plane), points_(std::move(points)) {
    CHECK(poses != nullptr);
    CHECK(!points_.empty());
    for (ChainPoint& point : points_) {
      CHECK_GE(point.w_edge, 0.0);
      if (plane_) {
        CHECK_GT(point.n_world.norm(), 0.0) << "normal must be non-zero";
        point.n_world.normalize();
      }
      point.w_edge = std::sqrt(point.w_edge);  // kept as sqrt(w_edge) from here on
    }
    set_num_residuals(static_cast<int>(points_.size()) * (plane_ ? 1 : 3));
    mutable_parameter_block_sizes()->push_back(6);
    if (poses->num_joints() > 0) mutable_parameter_block_sizes()->push_back(poses->num_joints());
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const int n = poses_->num_joints();
    (void)parameters;  // the poses at them come from poses_ (see LinkPoseSource)
    const LinkPoseJacobian& pose = poses_->At(link_);
    const int rows = plane_ ? 1 : 3;
    for (size_t s = 0; s < points_.size(); ++s) {
      const ChainPoint& point = points_[s];
      const int row = static_cast<int>(s) * rows;
      const Eigen::Vector3d d = point.w_edge * (pose.R * point.p_link + pose.t - point.q_world);
      if (plane_) {
        residuals[row] = point.n_world.dot(d);
      } else {
        for (int r = 0; r < 3; ++r) residuals[row + r] = d[r];
      }
      if (jacobians == nullptr) continue;
      for (int block = 0; block < (n > 0 ? 2 : 1); ++block) {
        if (jacobians[block] == nullptr) continue;
        const int columns = block == 0 ? 6 : n;
        const int first = block == 0 ? 0 : 6;
        for (int k = 0; k < columns; ++k) {
          const size_t i = static_cast<size_t>(first + k);
          const Eigen::Vector3d dy = point.w_edge * (pose.dR[i] * point.p_link + pose.dt[i]);
          if (plane_) {
            jacobians[block][row * columns + k] = point.n_world.dot(dy);
          } else {
            for (int r = 0; r < 3; ++r) jacobians[block][(row + r) * columns + k] = dy[r];
          }
        }
      }
    }
    return true;
  }

 private:
  const LinkPoseSource* poses_;  // borrowed
  const int link_;
  const bool plane_;
  std::vector<ChainPoint> points_;  // w_edge holds sqrt(w_edge)
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_CHAIN_POINT_COST_H_
