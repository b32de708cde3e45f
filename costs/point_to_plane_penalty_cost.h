// Prismatic-joint rotation-lock constraint, paper Eq. (14) (Sec. 6.2.2): the
// signed distance of a transformed off-axis point to the reference plane
// P = {x : n^T (x - c0) = 0}:
//
//   r = sqrt(lambda) * n_world^T (R c_link + t - c0_world)    1 residual [m]
//
// r^2 = lambda * dist^2(R c + t, P). c_link: point off the joint axis, child
// link frame; c0_world: a point on the plane, world frame; n_world: plane
// normal, world frame (normalised here); lambda >= 0 (dimensionless).
// Unlike point_to_plane_cost.h (a data term weighted by w_edge), this is a
// kinematic penalty against a fixed plane of the parent.
//
// Pose parameterisation as in point_to_point_cost.h: rotation_world_link[3]
// angle-axis [rad], translation_world_link[3] [m]; maps link -> world.
#ifndef EDGEFIT_COSTS_POINT_TO_PLANE_PENALTY_COST_H_
#define EDGEFIT_COSTS_POINT_TO_PLANE_PENALTY_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>

namespace edgefit {

class PointToPlanePenaltyCost {
 public:
  PointToPlanePenaltyCost(const Eigen::Vector3d& c_link, const Eigen::Vector3d& c0_world,
                          const Eigen::Vector3d& n_world, double lambda)
      : c_link_(c_link),
        c0_world_(c0_world),
        n_world_(n_world.normalized()),
        sqrt_lambda_(std::sqrt(lambda)) {
    CHECK_GE(lambda, 0.0) << "lambda must be non-negative";
    CHECK_GT(n_world.norm(), 0.0) << "plane normal must be non-zero";
  }

  template <typename T>
  bool operator()(const T* const rotation_world_link, const T* const translation_world_link,
                  T* residual) const {
    Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_world_link(translation_world_link);

    const Eigen::Matrix<T, 3, 1> c_link = c_link_.cast<T>();
    Eigen::Matrix<T, 3, 1> c_world;
    ceres::AngleAxisRotatePoint(rotation_world_link, c_link.data(), c_world.data());
    c_world += t_world_link;

    residual[0] = T(sqrt_lambda_) * n_world_.cast<T>().dot(c_world - c0_world_.cast<T>());
    return true;
  }

  // Residuals: 1; parameter blocks: rotation_world_link[3] (angle-axis),
  // translation_world_link[3]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Vector3d& c_link, const Eigen::Vector3d& c0_world,
                                     const Eigen::Vector3d& n_world, double lambda) {
    return new ceres::AutoDiffCostFunction<PointToPlanePenaltyCost, 1, 3, 3>(
        new PointToPlanePenaltyCost(c_link, c0_world, n_world, lambda));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Vector3d c_link_;    // off-axis point, child link frame [m]
  const Eigen::Vector3d c0_world_;  // point on the reference plane, world [m]
  const Eigen::Vector3d n_world_;   // unit plane normal, world
  const double sqrt_lambda_;        // sqrt of the constraint weight lambda
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_POINT_TO_PLANE_PENALTY_COST_H_
