#include "costs/joint_batch_cost.h"

#include <glog/logging.h>

#include <cmath>

namespace edgefit {

JointBatchCost::JointBatchCost(Motion motion, const Eigen::Isometry3d& T_world_joint,
                               const Eigen::Vector3d& axis_joint)
    : motion_(motion),
      R_world_joint_(T_world_joint.linear()),
      t_world_joint_(T_world_joint.translation()),
      axis_joint_(axis_joint.normalized()) {
  CHECK_GT(axis_joint.norm(), 0.0) << "joint axis must be non-zero";
  mutable_parameter_block_sizes()->push_back(1);
  set_num_residuals(0);
}

void JointBatchCost::AddPoint(const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world,
                              double w_edge) {
  CHECK_GE(w_edge, 0.0) << "edge weight must be non-negative";
  terms_.push_back({p_child, q_world, Eigen::Vector3d::Zero(), std::sqrt(w_edge), false});
  set_num_residuals(num_residuals() + 3);
}

void JointBatchCost::AddPlane(const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world,
                              const Eigen::Vector3d& n_world, double w_edge) {
  CHECK_GE(w_edge, 0.0) << "edge weight must be non-negative";
  CHECK_GT(n_world.norm(), 0.0) << "normal must be non-zero";
  terms_.push_back({p_child, q_world, n_world.normalized(), std::sqrt(w_edge), true});
  set_num_residuals(num_residuals() + 1);
}

bool JointBatchCost::Evaluate(double const* const* parameters, double* residuals,
                              double** jacobians) const {
  const double q = parameters[0][0];
  const Eigen::Vector3d& a = axis_joint_;
  const double c = std::cos(q), s = std::sin(q);
  double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
  const Eigen::Vector3d dx_prismatic = R_world_joint_ * a;
  size_t row = 0;
  for (const Term& term : terms_) {
    const Eigen::Vector3d& p = term.p_child;
    Eigen::Vector3d x, dx;
    if (motion_ == Motion::kRevolute) {
      const Eigen::Vector3d a_x_p = a.cross(p);
      const double a_p = a.dot(p);
      x = R_world_joint_ * (p * c + a_x_p * s + a * (a_p * (1.0 - c))) + t_world_joint_;
      dx = R_world_joint_ * (-p * s + a_x_p * c + a * (a_p * s));
    } else {
      x = R_world_joint_ * (p + a * q) + t_world_joint_;
      dx = dx_prismatic;
    }
    const Eigen::Vector3d r = term.sqrt_w_edge * (x - term.q_world);
    if (term.plane) {
      residuals[row] = term.n_world.dot(r);
      if (jacobian != nullptr) jacobian[row] = term.sqrt_w_edge * term.n_world.dot(dx);
      row += 1;
    } else {
      Eigen::Map<Eigen::Vector3d>(residuals + row) = r;
      if (jacobian != nullptr) Eigen::Map<Eigen::Vector3d>(jacobian + row) = term.sqrt_w_edge * dx;
      row += 3;
    }
  }
  return true;
}

}  // namespace edgefit
