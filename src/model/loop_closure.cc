#include "edgefit/model/loop_closure.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace edgefit {

Status AddLoopClosure(const LoopClosureSpec& spec, KinematicModel* model) {
  const std::string where = "loop_closure '" + spec.name + "'";
  LoopClosure closure;
  closure.name = spec.name;
  closure.link_a = model->LinkIndex(spec.link_a);
  closure.link_b = model->LinkIndex(spec.link_b);
  if (closure.link_a < 0) return Status::Error(where + ": unknown link_a '" + spec.link_a + "'");
  if (closure.link_b < 0) return Status::Error(where + ": unknown link_b '" + spec.link_b + "'");
  closure.p_link_a = spec.p_link_a;
  closure.p_link_b = spec.p_link_b;
  if (spec.joints.empty()) return Status::Error(where + ": no joints listed");
  for (const std::string& name : spec.joints) {
    const int j = model->JointIndex(name);
    if (j < 0) return Status::Error(where + ": unknown joint '" + name + "'");
    const Joint& joint = model->joints()[j];
    if (!joint.IsMoving()) return Status::Error(where + ": joint '" + name + "' is fixed");
    if (joint.mimic_joint >= 0) {
      return Status::Error(where + ": joint '" + name + "' is already a mimic joint");
    }
    if (std::find(closure.joints.begin(), closure.joints.end(), j) != closure.joints.end()) {
      return Status::Error(where + ": joint '" + name + "' listed twice");
    }
    closure.joints.push_back(j);
  }
  model->mutable_loop_closures().push_back(closure);
  return Status::Ok();
}

Eigen::Vector3d LoopClosureResidual(const KinematicModel& model, const LoopClosure& closure,
                                    const std::vector<double>& q) {
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q);
  return T_world_link[closure.link_a] * closure.p_link_a -
         T_world_link[closure.link_b] * closure.p_link_b;
}

namespace {

// True when joint j lies on the path from the root to `link`.
bool IsAncestorJoint(const KinematicModel& model, int j, int link) {
  for (int k = model.links()[link].parent_joint; k >= 0;
       k = model.links()[model.joints()[k].parent_link].parent_joint) {
    if (k == j) return true;
  }
  return false;
}

// d p_world / d q_j for a point p_world fixed on a descendant of joint j.
Eigen::Vector3d PointDerivative(const Joint& joint, const Pose& T_world_parent,
                                const Eigen::Vector3d& p_world) {
  const Pose T_world_joint = T_world_parent * joint.T_parent_joint;
  const Eigen::Vector3d axis_world = T_world_joint.linear() * joint.axis;
  if (joint.type == JointType::kPrismatic) return axis_world;
  // A revolute joint's frame origin stays on its axis for any q.
  return axis_world.cross(p_world - T_world_joint.translation());
}

}  // namespace

Status SolveLoopClosure(const KinematicModel& model, const LoopClosure& closure,
                        std::vector<double>* q, double tolerance) {
  // Levenberg-Marquardt on r(x) = p_world(a) - p_world(b), x = q[closure.joints].
  // The mechanisms are small (1-3 unknowns), so a dense solve of
  // (J^T J + lambda diag(J^T J)) dx = -J^T r per step is cheap.
  constexpr int kMaxIterations = 200;
  constexpr double kTargetResidual = 1e-13;  // [m], far below any tolerance used.
  const int n = static_cast<int>(closure.joints.size());
  auto clamp_into_limits = [&](std::vector<double>* values) {
    for (int j : closure.joints) {
      const Joint& joint = model.joints()[j];
      if (joint.has_limits) (*values)[j] = std::clamp((*values)[j], joint.lower, joint.upper);
    }
  };
  clamp_into_limits(q);
  std::vector<double> trial = *q;
  Eigen::Vector3d r = LoopClosureResidual(model, closure, *q);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < kMaxIterations && r.norm() > kTargetResidual; ++iteration) {
    const std::vector<Pose> T_world_link = model.ForwardKinematics(*q);
    const Eigen::Vector3d p_a = T_world_link[closure.link_a] * closure.p_link_a;
    const Eigen::Vector3d p_b = T_world_link[closure.link_b] * closure.p_link_b;
    Eigen::Matrix<double, 3, Eigen::Dynamic> J(3, n);
    for (int k = 0; k < n; ++k) {
      const int j = closure.joints[k];
      const Joint& joint = model.joints()[j];
      const Pose& T_world_parent = T_world_link[joint.parent_link];
      J.col(k).setZero();
      if (IsAncestorJoint(model, j, closure.link_a)) {
        J.col(k) += PointDerivative(joint, T_world_parent, p_a);
      }
      if (IsAncestorJoint(model, j, closure.link_b)) {
        J.col(k) -= PointDerivative(joint, T_world_parent, p_b);
      }
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd Jtr = J.transpose() * r;
    bool improved = false;
    for (int attempt = 0; attempt < 20 && !improved; ++attempt) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * (JtJ.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd dx = A.ldlt().solve(-Jtr);
      trial = *q;
      for (int k = 0; k < n; ++k) trial[closure.joints[k]] += dx[k];
      clamp_into_limits(&trial);
      const Eigen::Vector3d r_trial = LoopClosureResidual(model, closure, trial);
      if (r_trial.squaredNorm() < r.squaredNorm()) {
        *q = trial;
        r = r_trial;
        lambda = std::max(lambda * 0.1, 1e-12);
        improved = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!improved) break;  // Converged to a (possibly constrained) minimum.
  }
  if (!(r.norm() <= tolerance)) {
    return Status::Error("loop closure '" + closure.name + "' cannot be closed within the joint " +
                         "limits: residual " + std::to_string(r.norm()) + " m");
  }
  return Status::Ok();
}

}  // namespace edgefit
