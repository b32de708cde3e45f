// LinkMotion: how the weighted ICP may move one link (paper Sec. 5-6).
//
//   kFree       any rigid motion T_world_link: the base link (Sec. 5.1.2, 6.1);
//   kRevolute   T_world_link = T_world_joint * Rot(axis_joint, theta)
//               (Sec. 5.2, revolute and continuous URDF joints);
//   kPrismatic  T_world_link = T_world_joint * Trans(d * axis_joint)
//               (Sec. 6.2).
//
// T_world_joint = T_world_parent * T_parent_joint is where the already fitted
// parent link puts the joint frame; axis_joint is the unit URDF axis in that
// frame. Joint values q are theta [rad] or d [m], as in KinematicModel.
#ifndef EDGEFIT_SOLVERS_REGISTRATION_LINK_MOTION_H_
#define EDGEFIT_SOLVERS_REGISTRATION_LINK_MOTION_H_

#include <Eigen/Core>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

struct LinkMotion {
  enum class Type { kFree, kRevolute, kPrismatic };

  Type type = Type::kFree;
  Pose T_world_joint = Pose::Identity();
  Eigen::Vector3d axis_joint = Eigen::Vector3d::UnitZ();  // unit
  bool has_limits = false;
  double lower = 0.0;  // [rad] or [m]
  double upper = 0.0;

  // A free link (6-DoF).
  static LinkMotion Free() { return LinkMotion(); }
  // The moving joint `joint` below a parent link at T_world_parent.
  // CHECK-fails on a fixed joint.
  static LinkMotion FromJoint(const Joint& joint, const Pose& T_world_parent);

  bool constrained() const { return type != Type::kFree; }
  // T_world_link for the joint value q (kFree: T_world_joint).
  Pose PoseAt(double q) const;
  // The joint value of the 1-DoF pose nearest to a free T_world_link (paper
  // Sec. 5.2.2 and 6.2.2, "projection onto the joint axis"):
  //   revolute:  theta = twist angle of R_joint_link about axis_joint (the
  //              swing-twist decomposition of its quaternion,
  //              theta = 2 atan2(axis . q_vec, q_w)), taken on the 2 pi branch
  //              nearest q_reference;
  //   prismatic: d = axis_joint . t_joint_link;
  // then clamped into [lower, upper] when has_limits. kFree: returns 0.
  double Project(const Pose& T_world_link, double q_reference) const;
  // Clamps q into the limits (unchanged without limits).
  double Clamp(double q) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_REGISTRATION_LINK_MOTION_H_
