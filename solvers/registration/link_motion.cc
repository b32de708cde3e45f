#include "solvers/registration/link_motion.h"

#include <glog/logging.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace edgefit {

LinkMotion LinkMotion::FromJoint(const Joint& joint, const Pose& T_world_parent) {
  CHECK(joint.IsMoving()) << "joint '" << joint.name << "' is fixed";
  LinkMotion motion;
  motion.type = joint.type == JointType::kPrismatic ? Type::kPrismatic : Type::kRevolute;
  motion.T_world_joint = T_world_parent * joint.T_parent_joint;
  motion.axis_joint = joint.axis.normalized();
  motion.has_limits = joint.has_limits;
  motion.lower = joint.lower;
  motion.upper = joint.upper;
  return motion;
}

Pose LinkMotion::PoseAt(double q) const {
  switch (type) {
    case Type::kFree:
      return T_world_joint;
    case Type::kRevolute:
      return T_world_joint * Eigen::AngleAxisd(q, axis_joint);
    case Type::kPrismatic:
      return T_world_joint * Eigen::Translation3d(q * axis_joint);
  }
  return T_world_joint;
}

double LinkMotion::Clamp(double q) const {
  return has_limits ? std::clamp(q, lower, upper) : q;
}

double LinkMotion::Project(const Pose& T_world_link, double q_reference) const {
  const Pose T_joint_link = T_world_joint.inverse() * T_world_link;
  switch (type) {
    case Type::kFree:
      return 0.0;
    case Type::kPrismatic:
      return Clamp(axis_joint.dot(T_joint_link.translation()));
    case Type::kRevolute: {
      const Eigen::Quaterniond q(T_joint_link.linear());
      double theta = 2.0 * std::atan2(axis_joint.dot(q.vec()), q.w());
      // Onto the 2 pi branch nearest the reference (continuous joints and
      // limits wider than one turn).
      theta += 2.0 * M_PI * std::round((q_reference - theta) / (2.0 * M_PI));
      return Clamp(theta);
    }
  }
  return 0.0;
}

}  // namespace edgefit
