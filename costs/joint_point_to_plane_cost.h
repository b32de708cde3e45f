// Joint-space point-to-plane residual: the planar variant of the joint-space
// data term (revolute_point_cost.h, prismatic_point_cost.h), as
// point_to_plane_cost.h is for the 6-DoF pose:
//
//   r = n_world^T r_point(q)                                 1 residual [m]
//   r_point(q) = sqrt(w_edge) (T_world_joint * Motion(axis, q) * p_child
//                              - q_world)
//
// r_point is the 3-vector of PointCost (RevolutePointCost: q = theta [rad],
// Motion a rotation about axis; PrismaticPointCost: q = d [m], a shift along
// it); n_world: unit normal of the plane, fixed for the solve (world frame,
// normalised here; see point_to_plane_cost.h). Sliding along the scanned surface costs nothing, so the ICP
// converges in a few iterations where point-to-point crawls.
//
// Parameter block: q[1].
#ifndef EDGEFIT_COSTS_JOINT_POINT_TO_PLANE_COST_H_
#define EDGEFIT_COSTS_JOINT_POINT_TO_PLANE_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <glog/logging.h>

#include <Eigen/Core>

namespace edgefit {

template <typename PointCost>
class JointPointToPlaneCost {
 public:
  JointPointToPlaneCost(const PointCost& point, const Eigen::Vector3d& n_world)
      : point_(point), n_world_(n_world.normalized()) {
    CHECK_GT(n_world.norm(), 0.0) << "normal must be non-zero";
  }

  template <typename T>
  bool operator()(const T* const q, T* residual) const {
    T r_point[3];
    if (!point_(q, r_point)) return false;
    residual[0] =
        T(n_world_.x()) * r_point[0] + T(n_world_.y()) * r_point[1] + T(n_world_.z()) * r_point[2];
    return true;
  }

  // Residuals: 1; parameter block: q[1]. The caller owns the result.
  static ceres::CostFunction* Create(const PointCost& point, const Eigen::Vector3d& n_world) {
    return new ceres::AutoDiffCostFunction<JointPointToPlaneCost, 1, 1>(
        new JointPointToPlaneCost(point, n_world));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const PointCost point_;
  const Eigen::Vector3d n_world_;  // unit normal at q_world, world frame
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_JOINT_POINT_TO_PLANE_COST_H_
