// Loop closures (paper Sec. 3.1, 5.3): a closed mechanism (balancer
// cylinder + piston, parallelogram) is kept a URDF tree by cutting it at one
// point; the sub-chain joints then follow the main chain because a point on
// link_a must coincide with a point on link_b. Declared in the URDF as an
// extension element under <robot>, which urdfdom ignores:
//
//   <loop_closure name="balancer" link_a="piston" point_a="0 0 0"
//                 link_b="link_2" point_b="0.3 0 0"
//                 joints="cylinder_joint piston_joint"/>
//
// point_a / point_b are in the link_a / link_b frames [m]; `joints` are the
// sub-chain joints solved for (revolute, continuous or prismatic).
#ifndef EDGEFIT_MODEL_LOOP_CLOSURE_H_
#define EDGEFIT_MODEL_LOOP_CLOSURE_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// A <loop_closure> element as written, names not yet resolved.
struct LoopClosureSpec {
  std::string name;
  std::string link_a, link_b;
  Eigen::Vector3d p_link_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_link_b = Eigen::Vector3d::Zero();
  std::vector<std::string> joints;
};

// Resolves the names of `spec` in `model` and appends the closure (call
// model->Finalize() afterwards). Fails, naming the closure, on unknown links
// or joints, fixed joints, or joints that are already mimic joints.
Status AddLoopClosure(const LoopClosureSpec& spec, KinematicModel* model);

// p_world(point_a) - p_world(point_b) [m] for full joint values q.
Eigen::Vector3d LoopClosureResidual(const KinematicModel& model, const LoopClosure& closure,
                                    const std::vector<double>& q);

// Solves closure.joints in *q so that the residual vanishes, every other
// joint held: Levenberg-Marquardt on the 3-vector residual with the
// analytic Jacobian (revolute: axis x (p - joint origin), prismatic: axis,
// both in world), warm-started from the values in *q, each step projected
// into the joint limits. Leaves the best values found in *q; fails when the
// residual norm stays above `tolerance` [m].
Status SolveLoopClosure(const KinematicModel& model, const LoopClosure& closure,
                        std::vector<double>* q, double tolerance);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_LOOP_CLOSURE_H_
