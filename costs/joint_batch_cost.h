// The joint-space data term of one whole ICP solve in a single residual
// block: for every correspondence the residuals of revolute_point_cost.h /
// prismatic_point_cost.h (3 each) or of joint_point_to_plane_cost.h (1 each),
// with the analytic derivative in the joint value q:
//
//   x(q)   = T_world_joint * Motion(axis, q) * p_child         [m]
//   point: r = sqrt(w_edge) (x(q) - q_world)                   3 residuals
//   plane: r = sqrt(w_edge) n_world^T (x(q) - q_world)         1 residual
//   revolute (q = theta [rad]), Rodrigues:
//     Motion p = p cos q + (a x p) sin q + a (a.p) (1 - cos q)
//     dx/dq    = R_world_joint (-p sin q + (a x p) cos q + a (a.p) sin q)
//   prismatic (q = d [m]):
//     Motion p = p + a q,   dx/dq = R_world_joint a
//
// T_world_joint: the joint frame in the world (parent pose * URDF origin);
// a: the unit joint axis in the joint frame; p_child: CAD sample, child link
// frame; q_world: its scan point; n_world: unit normal of the plane through
// q_world; w_edge >= 0: Eq. (6).
//
// Why one block: Ceres builds and evaluates a residual block in about a
// microsecond, which for 10^4 correspondences of a 1-parameter problem is
// most of the solve. The sum of squares is the same as with a block per
// correspondence, so under the trivial loss the problem is the same; a
// robust loss acts per block, so it needs the per-correspondence functors.
//
// Parameter block: q[1].
#ifndef EDGEFIT_COSTS_JOINT_BATCH_COST_H_
#define EDGEFIT_COSTS_JOINT_BATCH_COST_H_

#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace edgefit {

class JointBatchCost : public ceres::CostFunction {
 public:
  enum class Motion { kRevolute, kPrismatic };

  JointBatchCost(Motion motion, const Eigen::Isometry3d& T_world_joint,
                 const Eigen::Vector3d& axis_joint);

  // Terms; the block's residual count grows with each.
  void AddPoint(const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world, double w_edge);
  void AddPlane(const Eigen::Vector3d& p_child, const Eigen::Vector3d& q_world,
                const Eigen::Vector3d& n_world, double w_edge);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  struct Term {
    Eigen::Vector3d p_child;
    Eigen::Vector3d q_world;
    Eigen::Vector3d n_world;  // plane terms only
    double sqrt_w_edge = 1.0;
    bool plane = false;
  };
  const Motion motion_;
  const Eigen::Matrix3d R_world_joint_;
  const Eigen::Vector3d t_world_joint_;
  const Eigen::Vector3d axis_joint_;  // unit
  std::vector<Term> terms_;
};

}  // namespace edgefit

#endif  // EDGEFIT_COSTS_JOINT_BATCH_COST_H_
