#include "edgefit/model/kinematic_model.h"

#include <algorithm>
#include <deque>

#include <glog/logging.h>

#include "edgefit/model/loop_closure.h"

namespace edgefit {

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kFixed: return "fixed";
    case JointType::kRevolute: return "revolute";
    case JointType::kContinuous: return "continuous";
    case JointType::kPrismatic: return "prismatic";
  }
  return "unknown";
}

Pose Joint::T_parent_child(double q) const {
  switch (type) {
    case JointType::kRevolute:
    case JointType::kContinuous:
      return T_parent_joint * Eigen::AngleAxisd(q, axis);
    case JointType::kPrismatic:
      return T_parent_joint * Eigen::Translation3d(q * axis);
    case JointType::kFixed:
      break;
  }
  return T_parent_joint;
}

int KinematicModel::LinkIndex(const std::string& name) const {
  for (size_t i = 0; i < links_.size(); ++i) {
    if (links_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int KinematicModel::JointIndex(const std::string& name) const {
  for (size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<int> KinematicModel::IndependentJoints() const {
  std::vector<int> out;
  for (int j : joint_order_) {
    if (joints_[j].IsIndependent()) out.push_back(j);
  }
  return out;
}

std::vector<double> KinematicModel::ZeroJoints() const {
  std::vector<double> q(joints_.size(), 0.0);
  for (size_t j = 0; j < joints_.size(); ++j) {
    if (joints_[j].has_limits) q[j] = std::clamp(0.0, joints_[j].lower, joints_[j].upper);
  }
  return q;
}

Status KinematicModel::Finalize() {
  const int num_links = static_cast<int>(links_.size());
  const int num_joints = static_cast<int>(joints_.size());
  for (Link& link : links_) {
    link.parent_joint = -1;
    link.child_joints.clear();
  }
  for (int j = 0; j < num_joints; ++j) {
    const Joint& joint = joints_[j];
    if (joint.parent_link < 0 || joint.parent_link >= num_links || joint.child_link < 0 ||
        joint.child_link >= num_links) {
      return Status::Error("joint '" + joint.name + "': parent or child link missing");
    }
    Link& child = links_[joint.child_link];
    if (child.parent_joint >= 0) {
      return Status::Error("link '" + child.name + "' is the child of two joints ('" +
                           joints_[child.parent_joint].name + "', '" + joint.name + "')");
    }
    child.parent_joint = j;
    links_[joint.parent_link].child_joints.push_back(j);
  }
  root_link_ = -1;
  for (int l = 0; l < num_links; ++l) {
    if (links_[l].parent_joint >= 0) continue;
    if (root_link_ >= 0) {
      return Status::Error("two root links ('" + links_[root_link_].name + "', '" +
                           links_[l].name + "'): not a tree");
    }
    root_link_ = l;
  }
  if (root_link_ < 0) return Status::Error("no root link: the joints form a cycle");
  // Breadth-first from the root: parents before children.
  joint_order_.clear();
  std::deque<int> queue = {root_link_};
  std::vector<bool> seen(num_links, false);
  seen[root_link_] = true;
  while (!queue.empty()) {
    const int l = queue.front();
    queue.pop_front();
    for (int j : links_[l].child_joints) {
      joint_order_.push_back(j);
      const int c = joints_[j].child_link;
      if (seen[c]) return Status::Error("link '" + links_[c].name + "' reached twice");
      seen[c] = true;
      queue.push_back(c);
    }
  }
  if (static_cast<int>(joint_order_.size()) != num_joints) {
    return Status::Error("some links are not connected to the root link '" +
                         links_[root_link_].name + "' (a cycle?)");
  }
  // Mimic references and loop-closure ownership.
  for (Joint& joint : joints_) {
    joint.loop_closure = -1;
    if (joint.mimic_joint >= num_joints || joint.mimic_joint == &joint - joints_.data()) {
      return Status::Error("joint '" + joint.name + "': bad mimic reference");
    }
  }
  for (const Joint& joint : joints_) {  // a chain of mimics must end at a joint of its own
    int steps = 0;
    for (int m = joint.mimic_joint; m >= 0; m = joints_[static_cast<size_t>(m)].mimic_joint) {
      if (++steps > num_joints) {
        return Status::Error("joint '" + joint.name + "': its mimic joints form a cycle");
      }
    }
  }
  for (size_t c = 0; c < loop_closures_.size(); ++c) {
    const LoopClosure& closure = loop_closures_[c];
    if (closure.link_a < 0 || closure.link_a >= num_links || closure.link_b < 0 ||
        closure.link_b >= num_links || closure.joints.empty()) {
      return Status::Error("loop closure '" + closure.name + "': bad links or no joints");
    }
    for (int j : closure.joints) {
      if (j < 0 || j >= num_joints) {
        return Status::Error("loop closure '" + closure.name + "': bad joint index");
      }
      Joint& joint = joints_[j];
      if (!joint.IsMoving() || joint.mimic_joint >= 0 || joint.loop_closure >= 0) {
        return Status::Error("loop closure '" + closure.name + "': joint '" + joint.name +
                             "' is fixed, a mimic joint, or in another loop closure");
      }
      joint.loop_closure = static_cast<int>(c);
    }
  }
  return Status::Ok();
}

namespace {

// Moving joints on the path from the root to `link`.
void AppendPathJoints(const KinematicModel& model, int link, std::vector<int>* joints) {
  for (int j = model.links()[link].parent_joint; j >= 0;
       j = model.links()[model.joints()[j].parent_link].parent_joint) {
    if (model.joints()[j].IsMoving()) joints->push_back(j);
  }
}

}  // namespace

Status KinematicModel::ResolveDependentJoints(std::vector<double>* q, double tolerance) const {
  if (q->size() != joints_.size()) {
    return Status::Error("joint vector has " + std::to_string(q->size()) + " values, model '" +
                         name_ + "' has " + std::to_string(joints_.size()) + " joints");
  }
  // Resolve in dependency order: a mimic joint once its master is known, a
  // loop closure once every joint on the paths to its two links is known
  // (except its own). Repeated passes; no progress means a cycle.
  std::vector<bool> known(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j) {
    known[j] = !joints_[j].IsMoving() || joints_[j].IsIndependent();
  }
  std::vector<bool> closure_done(loop_closures_.size(), false);
  Status first_error;
  for (bool progress = true; progress;) {
    progress = false;
    for (size_t j = 0; j < joints_.size(); ++j) {
      const Joint& joint = joints_[j];
      if (known[j] || joint.mimic_joint < 0 || !known[joint.mimic_joint]) continue;
      (*q)[j] = joint.mimic_multiplier * (*q)[joint.mimic_joint] + joint.mimic_offset;
      known[j] = progress = true;
    }
    for (size_t c = 0; c < loop_closures_.size(); ++c) {
      if (closure_done[c]) continue;
      const LoopClosure& closure = loop_closures_[c];
      std::vector<int> needed;
      AppendPathJoints(*this, closure.link_a, &needed);
      AppendPathJoints(*this, closure.link_b, &needed);
      const bool ready = std::all_of(needed.begin(), needed.end(), [&](int j) {
        return known[j] || joints_[j].loop_closure == static_cast<int>(c);
      });
      if (!ready) continue;
      const Status status = SolveLoopClosure(*this, closure, q, tolerance);
      if (!status.ok() && first_error.ok()) first_error = status;
      for (int j : closure.joints) known[j] = true;
      closure_done[c] = progress = true;
    }
  }
  for (size_t j = 0; j < joints_.size(); ++j) {
    if (!known[j]) {
      return Status::Error("joint '" + joints_[j].name +
                           "': mimic / loop-closure dependencies form a cycle");
    }
  }
  return first_error;
}

std::vector<Pose> KinematicModel::ForwardKinematics(const std::vector<double>& q,
                                                    const Pose& T_world_root) const {
  CHECK_EQ(q.size(), joints_.size()) << "joint vector size for model '" << name_ << "'";
  std::vector<Pose> T_world_link(links_.size(), Pose::Identity());
  if (root_link_ < 0) return T_world_link;
  T_world_link[root_link_] = T_world_root;
  for (int j : joint_order_) {  // Parents first, so the parent pose is ready.
    const Joint& joint = joints_[j];
    T_world_link[joint.child_link] = T_world_link[joint.parent_link] * joint.T_parent_child(q[j]);
  }
  return T_world_link;
}

Eigen::AlignedBox3d KinematicModel::BoundingBox(const std::vector<double>& q,
                                                const Pose& T_world_root) const {
  const std::vector<Pose> T_world_link = ForwardKinematics(q, T_world_root);
  Eigen::AlignedBox3d box;
  for (size_t l = 0; l < links_.size(); ++l) {
    if (!links_[l].mesh.empty()) box.extend(links_[l].mesh.BoundingBox(T_world_link[l]));
  }
  return box;
}

}  // namespace edgefit
