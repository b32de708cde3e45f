// Revolute-joint axis-point penalty, paper Eq. (10) (Sec. 5.2.2):
//
//   r = sqrt(lambda) * (R a_link + t - a0_world)             3 residuals [m]
//
// One instance per axis point: (a, a0) and (b, b0). a_link is a point on the
// joint axis expressed in the child link frame; a0_world is the same axis
// point as placed by the (already fitted) parent link, in the world frame.
// lambda >= 0 balances the kinematic constraint against the data term
// (dimensionless; residual units follow the data term's metres).
//
// Pose parameterisation as in point_to_point_cost.h: rotation_world_link[3]
// angle-axis [rad], translation_world_link[3] [m]; maps link -> world.
#ifndef EDGEFIT_COSTS_AXIS_POINT_COST_H_
#define EDGEFIT_COSTS_AXIS_POINT_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>

namespace edgefit {

class AxisPointCost {
 public:
  AxisPointCost(const Eigen::Vector3d& a_link, const Eigen::Vector3d& a0_world, double lambda)
      : a_link_(a_link), a0_world_(a0_world), sqrt_lambda_(std::sqrt(lambda)) {
    CHECK_GE(lambda, 0.0) << "lambda must be non-negative";
  }

  template <typename T>
  bool operator()(const T* const rotation_world_link, const T* const translation_world_link,
                  T* residuals_ptr) const {
    Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_world_link(translation_world_link);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> residuals(residuals_ptr);

    const Eigen::Matrix<T, 3, 1> a_link = a_link_.cast<T>();
    Eigen::Matrix<T, 3, 1> a_world;
    ceres::AngleAxisRotatePoint(rotation_world_link, a_link.data(), a_world.data());
    a_world += t_world_link;

    residuals = T(sqrt_lambda_) * (a_world - a0_world_.cast<T>());
    return true;
  }

  // Residuals: 3; parameter blocks: rotation_world_link[3] (angle-axis),
  // translation_world_link[3]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Vector3d& a_link, const Eigen::Vector3d& a0_world,
                                     double lambda) {
    return new ceres::AutoDiffCostFunction<AxisPointCost, 3, 3, 3>(
        new AxisPointCost(a_link, a0_world, lambda));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Vector3d a_link_;    // axis point, child link frame [m]
  const Eigen::Vector3d a0_world_;  // same axis point from the parent, world [m]
  const double sqrt_lambda_;        // sqrt of the constraint weight lambda
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_AXIS_POINT_COST_H_
