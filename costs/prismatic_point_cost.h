// Joint-space point-to-point residual for a prismatic joint: the direct 1-DoF
// parameterisation of the Sec. 6.2 fit (the alternative to the 6-DoF
// constrained ICP of Eq. (14)). With the displacement d as the only parameter,
// the data term becomes
//
//   r = sqrt(w_edge) * (T_world_parent * T_parent_joint * Trans(d * axis)
//                       * p_child - q_world)                 3 residuals [m]
//
// T_world_parent: the fitted parent link pose; T_parent_joint: the URDF
// joint origin; axis: URDF joint axis in the joint frame (normalised here);
// the child link frame is the joint frame translated by d [m] along axis.
// p_child: CAD point, child link frame; q_world: its scan correspondence;
// w_edge >= 0: Eq. (6).
//
// Parameter block: d[1] [m].
#ifndef EDGEFIT_COSTS_PRISMATIC_POINT_COST_H_
#define EDGEFIT_COSTS_PRISMATIC_POINT_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace edgefit {

class PrismaticPointCost {
 public:
  PrismaticPointCost(const Eigen::Isometry3d& T_world_parent,
                     const Eigen::Isometry3d& T_parent_joint, const Eigen::Vector3d& axis_joint,
                     const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world, double w_edge)
      : R_world_joint_((T_world_parent * T_parent_joint).linear()),
        t_world_joint_((T_world_parent * T_parent_joint).translation()),
        axis_joint_(axis_joint.normalized()),
        p_child_(p_child),
        q_world_(q_world),
        sqrt_w_edge_(std::sqrt(w_edge)) {
    CHECK_GE(w_edge, 0.0) << "edge weight must be non-negative";
    CHECK_GT(axis_joint.norm(), 0.0) << "joint axis must be non-zero";
  }

  template <typename T>
  bool operator()(const T* const d, T* residuals_ptr) const {
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residuals(residuals_ptr);

    const Eigen::Matrix<T, 3, 1> p_joint = p_child_.cast<T>() + axis_joint_.cast<T>() * d[0];
    const Eigen::Matrix<T, 3, 1> p_world =
        R_world_joint_.cast<T>() * p_joint + t_world_joint_.cast<T>();
    residuals = T(sqrt_w_edge_) * (p_world - q_world_.cast<T>());
    return true;
  }

  // Residuals: 3; parameter block: d[1] [m]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Isometry3d& T_world_parent,
                                     const Eigen::Isometry3d& T_parent_joint,
                                     const Eigen::Vector3d& axis_joint,
                                     const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world,
                                     double w_edge) {
    return new ceres::AutoDiffCostFunction<PrismaticPointCost, 3, 1>(new PrismaticPointCost(
        T_world_parent, T_parent_joint, axis_joint, p_child, q_world, w_edge));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Matrix3d R_world_joint_;  // rotation of T_world_parent * T_parent_joint
  const Eigen::Vector3d t_world_joint_;  // its translation [m]
  const Eigen::Vector3d axis_joint_;     // unit joint axis, joint frame
  const Eigen::Vector3d p_child_;        // CAD point, child link frame [m]
  const Eigen::Vector3d q_world_;        // scan point, world frame [m]
  const double sqrt_w_edge_;             // sqrt of the Eq. (6) edge weight
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_PRISMATIC_POINT_COST_H_
