#include "edgefit/pipeline/fit_errors.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace edgefit {

Status CompareWithTruth(const KinematicModel& model, const std::vector<double>& q_fit,
                        const Pose& T_world_base_fit,
                        const std::vector<std::pair<std::string, double>>& truth_joints,
                        const Pose& T_world_base_truth, FitErrors* errors) {
  *errors = FitErrors();
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const Joint& joint = model.joints()[j];
    if (!joint.IsMoving()) continue;
    const auto it = std::find_if(truth_joints.begin(), truth_joints.end(),
                                 [&joint](const auto& named) { return named.first == joint.name; });
    if (it == truth_joints.end()) {
      return Status::Error("the truth has no value for joint '" + joint.name + "'");
    }
    JointError e;
    e.name = joint.name;
    e.prismatic = joint.type == JointType::kPrismatic;
    e.independent = joint.IsIndependent();
    e.truth = it->second;
    e.fit = q_fit[j];
    double difference = e.fit - e.truth;
    // A scan cannot tell theta from theta + 2 pi (joints with more than a
    // turn of range): revolute errors are taken modulo a turn.
    if (joint.type != JointType::kPrismatic) difference = std::remainder(difference, 2.0 * M_PI);
    e.error = std::abs(difference);
    errors->joints.push_back(e);
  }
  const Pose delta = T_world_base_truth.inverse() * T_world_base_fit;
  errors->base_translation = delta.translation().norm();
  errors->base_rotation = Eigen::AngleAxisd(delta.linear()).angle();
  return Status::Ok();
}

}  // namespace edgefit
