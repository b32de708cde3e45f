#include "edgefit/model/frozen_joints.h"

#include <cmath>
#include <cstdio>

namespace edgefit {
namespace {

// Marks joint j and, recursively, the mimic joints that follow it, with
// their values from q.
void HoldWithMimics(const KinematicModel& model, int j, std::vector<double>* q,
                    std::vector<bool>* held) {
  (*held)[static_cast<size_t>(j)] = true;
  for (size_t k = 0; k < model.joints().size(); ++k) {
    const Joint& joint = model.joints()[k];
    if (joint.mimic_joint != j || (*held)[k]) continue;
    (*q)[k] = joint.mimic_multiplier * (*q)[static_cast<size_t>(j)] + joint.mimic_offset;
    HoldWithMimics(model, static_cast<int>(k), q, held);
  }
}

// The held joints and the values of the original model's q they take.
Status HeldJoints(const KinematicModel& model, const KnownJoints& known, std::vector<double>* q,
                  std::vector<bool>* held) {
  *q = model.ZeroJoints();
  held->assign(model.joints().size(), false);
  std::vector<bool> named(model.joints().size(), false);
  for (const auto& [name, value] : known) {
    const int j = model.JointIndex(name);
    if (j < 0) return Status::Error("known joint '" + name + "': the model has no such joint");
    const Joint& joint = model.joints()[static_cast<size_t>(j)];
    if (!joint.IsMoving()) return Status::Error("known joint '" + name + "' is fixed");
    if (joint.mimic_joint >= 0) {
      return Status::Error("known joint '" + name + "' mimics '" +
                           model.joints()[static_cast<size_t>(joint.mimic_joint)].name +
                           "': give that joint");
    }
    if (joint.loop_closure >= 0) {
      return Status::Error("known joint '" + name +
                           "' follows a loop closure: give the main chain's joints");
    }
    if (named[static_cast<size_t>(j)]) {
      return Status::Error("known joint '" + name + "' is given twice");
    }
    if (!std::isfinite(value) ||
        (joint.has_limits && (value < joint.lower - 1e-9 || value > joint.upper + 1e-9))) {
      char line[200];
      std::snprintf(line, sizeof(line), "known joint '%s' = %.6g is outside its limits [%.6g, %.6g]",
                    name.c_str(), value, joint.lower, joint.upper);
      return Status::Error(line);
    }
    named[static_cast<size_t>(j)] = true;
    (*q)[static_cast<size_t>(j)] = value;
    HoldWithMimics(model, j, q, held);
  }
  return Status::Ok();
}

}  // namespace

Status FreezeJoints(const KinematicModel& model, const KnownJoints& known, KinematicModel* frozen) {
  std::vector<double> q;
  std::vector<bool> held;
  EDGEFIT_RETURN_IF_ERROR(HeldJoints(model, known, &q, &held));
  *frozen = model;
  for (size_t j = 0; j < held.size(); ++j) {
    if (!held[j]) continue;
    Joint& joint = frozen->mutable_joints()[j];
    joint.T_parent_joint = joint.T_parent_child(q[j]);
    joint.type = JointType::kFixed;
    joint.has_limits = false;
    joint.lower = joint.upper = 0.0;
    joint.mimic_joint = -1;
  }
  return frozen->Finalize();
}

void SetKnownJoints(const KinematicModel& model, const KnownJoints& known,
                    std::vector<double>* q) {
  std::vector<double> values;
  std::vector<bool> held;
  if (!HeldJoints(model, known, &values, &held).ok()) return;  // FreezeJoints said why
  for (size_t j = 0; j < held.size() && j < q->size(); ++j) {
    if (held[j]) (*q)[j] = values[j];
  }
}

}  // namespace edgefit
