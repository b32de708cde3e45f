// Edge-weighted point-to-plane residual, the planar variant of the Eq. (8)
// data term (Sec. 5.1.2):
//
//   r = sqrt(w_edge) * n_world^T (R p_link + t - q_world)     1 residual [m]
//
// p_link: CAD point in the link frame; q_world: its scan correspondence;
// n_world: unit normal of the plane, fixed for the solve (world frame,
// normalised here): the CAD sample's, posed at the current estimate, or the
// target's from the edge stage (WeightedIcpOptions::plane_normals);
// w_edge >= 0: edge weight of Eq. (6).
//
// Pose parameterisation as in point_to_point_cost.h: rotation_world_link[3]
// angle-axis [rad], translation_world_link[3] [m]; maps link -> world.
#ifndef EDGEFIT_COSTS_POINT_TO_PLANE_COST_H_
#define EDGEFIT_COSTS_POINT_TO_PLANE_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>

namespace edgefit {

class PointToPlaneCost {
 public:
  PointToPlaneCost(const Eigen::Vector3d& p_link, const Eigen::Vector3d& q_world,
                   const Eigen::Vector3d& n_world, double w_edge)
      : p_link_(p_link),
        q_world_(q_world),
        n_world_(n_world.normalized()),
        sqrt_w_edge_(std::sqrt(w_edge)) {
    CHECK_GE(w_edge, 0.0) << "edge weight must be non-negative";
    CHECK_GT(n_world.norm(), 0.0) << "target normal must be non-zero";
  }

  template <typename T>
  bool operator()(const T* const rotation_world_link, const T* const translation_world_link,
                  T* residual) const {
    Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_world_link(translation_world_link);

    const Eigen::Matrix<T, 3, 1> p_link = p_link_.cast<T>();
    Eigen::Matrix<T, 3, 1> p_world;
    ceres::AngleAxisRotatePoint(rotation_world_link, p_link.data(), p_world.data());
    p_world += t_world_link;

    residual[0] = T(sqrt_w_edge_) * n_world_.cast<T>().dot(p_world - q_world_.cast<T>());
    return true;
  }

  // Residuals: 1; parameter blocks: rotation_world_link[3] (angle-axis),
  // translation_world_link[3]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Vector3d& p_link, const Eigen::Vector3d& q_world,
                                     const Eigen::Vector3d& n_world, double w_edge) {
    return new ceres::AutoDiffCostFunction<PointToPlaneCost, 1, 3, 3>(
        new PointToPlaneCost(p_link, q_world, n_world, w_edge));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Vector3d p_link_;   // CAD point, link frame [m]
  const Eigen::Vector3d q_world_;  // scan point, world frame [m]
  const Eigen::Vector3d n_world_;  // unit target normal, world frame
  const double sqrt_w_edge_;       // sqrt of the Eq. (6) edge weight
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_POINT_TO_PLANE_COST_H_
