// Prismatic-joint axial constraint, paper Eq. (14) (Sec. 6.2.2): the distance
// of a transformed axis point to the parent's joint line L = {l0 + s l}:
//
//   r = sqrt(lambda) * (I - l l^T) (R a_link + t - l0_world)  3 residuals [m]
//
// |r|^2 = lambda * dist^2(R a + t, L). One instance per axis point (a and b).
// a_link: point on the joint axis, child link frame; l0_world: a point on the
// line, world frame; l_world: line direction, world frame (normalised here);
// lambda >= 0: constraint weight (dimensionless). The residual is the
// component orthogonal to l, so it has rank 2 although it has 3 entries.
//
// Pose parameterisation as in point_to_point_cost.h: rotation_world_link[3]
// angle-axis [rad], translation_world_link[3] [m]; maps link -> world.
#ifndef EDGEFIT_COSTS_POINT_TO_LINE_COST_H_
#define EDGEFIT_COSTS_POINT_TO_LINE_COST_H_

#include <ceres/autodiff_cost_function.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <Eigen/Core>
#include <cmath>

namespace edgefit {

class PointToLineCost {
 public:
  PointToLineCost(const Eigen::Vector3d& a_link, const Eigen::Vector3d& l0_world,
                  const Eigen::Vector3d& l_world, double lambda)
      : a_link_(a_link),
        l0_world_(l0_world),
        l_world_(l_world.normalized()),
        sqrt_lambda_(std::sqrt(lambda)) {
    CHECK_GE(lambda, 0.0) << "lambda must be non-negative";
    CHECK_GT(l_world.norm(), 0.0) << "line direction must be non-zero";
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

    const Eigen::Matrix<T, 3, 1> l = l_world_.cast<T>();
    const Eigen::Matrix<T, 3, 1> d = a_world - l0_world_.cast<T>();
    residuals = T(sqrt_lambda_) * (d - l * l.dot(d));
    return true;
  }

  // Residuals: 3; parameter blocks: rotation_world_link[3] (angle-axis),
  // translation_world_link[3]. The caller owns the result.
  static ceres::CostFunction* Create(const Eigen::Vector3d& a_link, const Eigen::Vector3d& l0_world,
                                     const Eigen::Vector3d& l_world, double lambda) {
    return new ceres::AutoDiffCostFunction<PointToLineCost, 3, 3, 3>(
        new PointToLineCost(a_link, l0_world, l_world, lambda));
  }

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  const Eigen::Vector3d a_link_;    // axis point, child link frame [m]
  const Eigen::Vector3d l0_world_;  // point on the parent's joint line, world [m]
  const Eigen::Vector3d l_world_;   // unit line direction, world
  const double sqrt_lambda_;        // sqrt of the constraint weight lambda
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_POINT_TO_LINE_COST_H_
