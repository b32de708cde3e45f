// Ceres manifold for the angle-axis rotation block of the 6-DoF pose
// (costs/point_to_point_cost.h: rotation_world_link[3], R = exp([w]x)).
//
// Plus is a left-multiplicative update in the tangent space,
//
//   Plus(w, delta)  = log(exp([delta]x) exp([w]x))
//   Minus(y, w)     = log(exp([y]x) exp([w]x)^T),
//
// so a step delta [rad] rotates the current rotation by |delta| about a fixed
// world axis whatever w is. Plain vector addition of angle-axis vectors (the
// Euclidean default) is ill-conditioned near |w| = pi, where many vectors
// describe nearly the same rotation; link poses in the world frame reach any
// angle, so the pose stages use this manifold. Evaluated through unit
// quaternions (ceres/rotation.h) and differentiated by ceres::AutoDiffManifold.
#ifndef EDGEFIT_SOLVERS_REGISTRATION_ROTATION_MANIFOLD_H_
#define EDGEFIT_SOLVERS_REGISTRATION_ROTATION_MANIFOLD_H_

#include <ceres/autodiff_manifold.h>
#include <ceres/rotation.h>

namespace edgefit {

struct AngleAxisLeftPlus {
  template <typename T>
  bool Plus(const T* x, const T* delta, T* x_plus_delta) const {
    T q_x[4], q_delta[4], q_out[4];
    ceres::AngleAxisToQuaternion(x, q_x);
    ceres::AngleAxisToQuaternion(delta, q_delta);
    ceres::QuaternionProduct(q_delta, q_x, q_out);
    ceres::QuaternionToAngleAxis(q_out, x_plus_delta);
    return true;
  }

  template <typename T>
  bool Minus(const T* y, const T* x, T* y_minus_x) const {
    T q_y[4], q_x[4], q_out[4];
    ceres::AngleAxisToQuaternion(y, q_y);
    ceres::AngleAxisToQuaternion(x, q_x);
    q_x[1] = -q_x[1];  // conjugate = inverse of a unit quaternion
    q_x[2] = -q_x[2];
    q_x[3] = -q_x[3];
    ceres::QuaternionProduct(q_y, q_x, q_out);
    ceres::QuaternionToAngleAxis(q_out, y_minus_x);
    return true;
  }
};

// Ambient and tangent size 3. The caller (usually a ceres::Problem) owns it.
inline ceres::Manifold* NewAngleAxisManifold() {
  return new ceres::AutoDiffManifold<AngleAxisLeftPlus, 3, 3>;
}

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_ROTATION_MANIFOLD_H_
