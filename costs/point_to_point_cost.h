// Edge-weighted point-to-point residual of the weighted ICP, paper Eq. (8)
// (Sec. 5.1.2; also the data term of Eqs. (10) and (14)):
//
//   r = sqrt(w_edge) * (R p_link + t - q_world)          3 residuals [m]
//
// so that 1/2 |r|^2 = 1/2 w_edge |R p + t - q|^2 is the i-th summand of
// E_base. p_link is a CAD point in the link (source) frame, q_world its
// corresponding scan point in the world frame, w_edge >= 0 the edge weight of
// Eq. (6) (dimensionless).
//
// Pose parameterisation (all 6-DoF functors in costs/): two parameter blocks,
//   rotation_world_link[3]     angle-axis (axis * angle [rad]), R = exp([w]x)
//   translation_world_link[3]  t [m]
// T_world_link = (R, t) maps link-frame points into the world.
#ifndef EDGEFIT_COSTS_POINT_TO_POINT_COST_H_
#define EDGEFIT_COSTS_POINT_TO_POINT_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>

namespace edgefit {

class PointToPointCost {
 public:
  PointToPointCost(const Eigen::Vector3d& p_link, const Eigen::Vector3d& q_world, double w_edge)
      : p_link_(p_link), q_world_(q_world), sqrt_w_edge_(std::sqrt(w_edge)) {
    CHECK_GE(w_edge, 0.0) << "edge weight must be non-negative";
  }

  template <typename T>
  bool operator()(const T* const rotation_world_link, const T* const translation_world_link,
                  T* residuals_ptr) const {
    Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_world_link(translation_world_link);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residuals(residuals_ptr);

    const Eigen::Matrix<T, 3, 1> p_link = p_link_.cast<T>();
    Eigen::Matrix<T, 3, 1> p_world;
    ceres::AngleAxisRotatePoint(rotation_world_link, p_link.data(), p_world.data());
    p_world += t_world_link;

    residuals = T(sqrt_w_edge_) * (p_world - q_world_.cast<T>());
    return true;
  }

  // Residuals: 3; parameter blocks: rotation_world_link[3] (angle-axis),
  // translation_world_link[3]. Ownership of the result passes to the caller
  // (usually a ceres::Problem).
  static ceres::CostFunction* Create(const Eigen::Vector3d& p_link, const Eigen::Vector3d& q_world,
                                     double w_edge) {
    return new ceres::AutoDiffCostFunction<PointToPointCost, 3, 3, 3>(
        new PointToPointCost(p_link, q_world, w_edge));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Vector3d p_link_;   // CAD point, link frame [m]
  const Eigen::Vector3d q_world_;  // corresponding scan point, world frame [m]
  const double sqrt_w_edge_;       // sqrt of the Eq. (6) edge weight
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_POINT_TO_POINT_COST_H_
