// Joint-space point-to-point residual for a revolute joint: the direct 1-DoF
// parameterisation of the Sec. 5.2 fit (the alternative to the 6-DoF
// axis-constrained ICP of Eq. (10)). With the joint angle theta as the only
// parameter, the data term of Eqs. (8)/(10) becomes
//
//   r = sqrt(w_edge) * (T_world_parent * T_parent_joint * Rot(axis, theta)
//                       * p_child - q_world)                 3 residuals [m]
//
// T_world_parent: the fitted parent link pose; T_parent_joint: the URDF
// joint origin (parent link -> joint frame); axis: URDF joint axis in the
// joint frame (normalised here); the child link frame is the joint frame
// rotated by theta [rad] about axis (URDF convention). p_child: CAD point,
// child link frame; q_world: its scan correspondence; w_edge >= 0: Eq. (6).
// Rot(axis, theta) is evaluated by Rodrigues' formula.
//
// Parameter block: theta[1] [rad].
#ifndef EDGEFIT_COSTS_REVOLUTE_POINT_COST_H_
#define EDGEFIT_COSTS_REVOLUTE_POINT_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace edgefit {

class RevolutePointCost {
 public:
  RevolutePointCost(const Eigen::Isometry3d& T_world_parent,
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
  bool operator()(const T* const theta, T* residuals_ptr) const {
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residuals(residuals_ptr);
    using std::cos;
    using std::sin;

    // Rodrigues: Rot(a, th) p = p cos th + (a x p) sin th + a (a.p)(1 - cos th).
    const Eigen::Matrix<T, 3, 1> a = axis_joint_.cast<T>();
    const Eigen::Matrix<T, 3, 1> p = p_child_.cast<T>();
    const T c = cos(theta[0]);
    const T s = sin(theta[0]);
    const Eigen::Matrix<T, 3, 1> p_joint = p * c + a.cross(p) * s + a * (a.dot(p) * (T(1) - c));

    const Eigen::Matrix<T, 3, 1> p_world =
        R_world_joint_.cast<T>() * p_joint + t_world_joint_.cast<T>();
    residuals = T(sqrt_w_edge_) * (p_world - q_world_.cast<T>());
    return true;
  }

  // Residuals: 3; parameter block: theta[1] [rad]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Isometry3d& T_world_parent,
                                     const Eigen::Isometry3d& T_parent_joint,
                                     const Eigen::Vector3d& axis_joint,
                                     const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world,
                                     double w_edge) {
    return new ceres::AutoDiffCostFunction<RevolutePointCost, 3, 1>(new RevolutePointCost(
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

#endif  // EDGEFIT_COSTS_REVOLUTE_POINT_COST_H_
