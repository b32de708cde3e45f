#include "edgefit/bench/fit_errors.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace edgefit {

int ToolTipLink(const KinematicModel& model) {
  int best = model.root_link();
  int best_revolute = -1, best_fixed = -1;
  for (size_t l = 0; l < model.links().size(); ++l) {
    int revolute = 0, fixed = 0;
    for (int j = model.links()[l].parent_joint; j >= 0;) {
      const Joint& joint = model.joints()[static_cast<size_t>(j)];
      revolute += joint.type == JointType::kRevolute || joint.type == JointType::kContinuous;
      fixed += joint.type == JointType::kFixed;
      j = model.links()[static_cast<size_t>(joint.parent_link)].parent_joint;
    }
    if (revolute > best_revolute || (revolute == best_revolute && fixed > best_fixed)) {
      best = static_cast<int>(l);
      best_revolute = revolute;
      best_fixed = fixed;
    }
  }
  return best;
}

Pose SurveyFrame(const std::vector<Pose>& T_world_scanners_true,
                 const std::vector<Pose>& T_survey_scanners_written) {
  const size_t n = T_world_scanners_true.size();
  if (n == 0 || T_survey_scanners_written.size() != n) return Pose::Identity();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero(), translation = Eigen::Vector3d::Zero();
  for (size_t s = 0; s < n; ++s) {
    const Pose T_survey_world = T_survey_scanners_written[s] * T_world_scanners_true[s].inverse();
    const Eigen::AngleAxisd angle_axis(T_survey_world.linear());
    rotation += angle_axis.angle() * angle_axis.axis();
    translation += T_survey_world.translation();
  }
  rotation /= static_cast<double>(n);
  Pose T_survey_world = Pose::Identity();
  if (rotation.norm() > 0.0) {
    T_survey_world.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).matrix();
  }
  T_survey_world.translation() = translation / static_cast<double>(n);
  return T_survey_world;
}

Status CompareWithTruth(const KinematicModel& model, const std::vector<double>& q_fit,
                        const Pose& T_world_base_fit,
                        const std::vector<std::pair<std::string, double>>& truth_joints,
                        const Pose& T_world_base_truth_given, const Pose& T_survey_world,
                        FitErrors* errors, const BaseSymmetry& symmetry) {
  *errors = FitErrors();
  std::vector<std::pair<std::string, double>> truth_named = truth_joints;
  Pose T_world_base_truth = T_world_base_truth_given;
  if (symmetry.joint >= 0) {  // the truth's placement nearest the fit's
    const Joint& j1 = model.joints()[static_cast<size_t>(symmetry.joint)];
    for (auto& [name, value] : truth_named) {
      if (name != j1.name) continue;
      const double fit = q_fit[static_cast<size_t>(symmetry.joint)];
      double best = value;
      for (const double t : symmetry.turns) {
        if (std::abs(std::remainder(fit - (value - t), 2.0 * M_PI)) <
            std::abs(std::remainder(fit - best, 2.0 * M_PI))) {
          best = value - t;
        }
      }
      T_world_base_truth = TurnBaseForJoint(model, symmetry.joint, T_world_base_truth, value, best);
      value = best;
    }
  }
  std::vector<double> q_truth(model.joints().size(), 0.0);
  for (const int index : model.joint_order()) {  // parents first: base to tool
    const size_t j = static_cast<size_t>(index);
    const Joint& joint = model.joints()[j];
    if (!joint.IsMoving()) continue;
    const auto it = std::find_if(truth_named.begin(), truth_named.end(),
                                 [&joint](const auto& named) { return named.first == joint.name; });
    if (it == truth_named.end()) {
      return Status::Error("the truth has no value for joint '" + joint.name + "'");
    }
    JointError e;
    e.name = joint.name;
    e.joint = static_cast<int>(j);
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
    q_truth[j] = e.truth;
  }
  const int tip = ToolTipLink(model);
  if (tip >= 0) {
    errors->tool_tip_link = model.links()[static_cast<size_t>(tip)].name;
    const size_t t = static_cast<size_t>(tip);
    errors->tool_tip = (model.ForwardKinematics(q_fit, T_world_base_fit)[t].translation() -
                        model.ForwardKinematics(q_truth, T_world_base_truth)[t].translation())
                           .norm();
  }
  const Pose delta = T_world_base_truth.inverse() * T_world_base_fit;
  errors->base_translation = delta.translation().norm();
  errors->base_rotation = Eigen::AngleAxisd(delta.linear()).angle();
  const Pose T_world_base_survey = T_survey_world * T_world_base_truth;
  const Pose delta_survey = T_world_base_survey.inverse() * T_world_base_fit;
  errors->base_translation_survey = delta_survey.translation().norm();
  errors->base_rotation_survey = Eigen::AngleAxisd(delta_survey.linear()).angle();
  const Eigen::AngleAxisd rotation_world(T_world_base_fit.linear() *
                                         T_world_base_survey.linear().transpose());
  errors->base_rotation_survey_world = rotation_world.angle() * rotation_world.axis();
  errors->base_translation_survey_world =
      T_world_base_fit.translation() - T_world_base_survey.translation();
  return Status::Ok();
}

void MarkUnobservableJoints(const std::vector<BodyQuality>& bodies, FitErrors* errors) {
  for (JointError& e : errors->joints) {
    for (const BodyQuality& b : bodies) {
      if (b.joint == e.name) e.unobservable = b.verdict == JointVerdict::kUnobservable;
    }
  }
}

int MatchTruthAsset(const std::vector<CellTruthAsset>& truth, const std::vector<bool>& taken,
                    const KinematicModel& model, const Pose& T_world_base, double max_distance) {
  int best = -1;
  double best_distance = max_distance;
  for (size_t a = 0; a < truth.size(); ++a) {
    if (a < taken.size() && taken[a]) continue;
    bool same_joints = !truth[a].truth.joints.empty();
    for (const auto& [name, value] : truth[a].truth.joints)
      same_joints = same_joints && model.JointIndex(name) >= 0;
    const double d =
        (truth[a].truth.T_world_base.translation() - T_world_base.translation()).norm();
    if (same_joints && d < best_distance) best = static_cast<int>(a), best_distance = d;
  }
  return best;
}

Status ScoreFit(const KinematicModel& model, const FitResult& fit, const Truth& truth,
                FitErrors* errors) {
  EDGEFIT_RETURN_IF_ERROR(CompareWithTruth(
      model, fit.q, fit.T_world_base, truth.joints, truth.T_world_base,
      SurveyFrame(truth.T_world_scanners, truth.sensor.T_world_scanners_written), errors,
      fit.base_symmetry));
  MarkUnobservableJoints(fit.bodies, errors);
  return Status::Ok();
}

nlohmann::json FitErrorsJson(const FitErrors& errors) {
  nlohmann::json joints = nlohmann::json::object();
  for (const JointError& j : errors.joints) joints[j.name] = j.error;
  return {{"joints", joints},
          {"base_translation_m", errors.base_translation},
          {"base_rotation_rad", errors.base_rotation},
          {"base_survey_translation_m", errors.base_translation_survey},
          {"base_survey_rotation_rad", errors.base_rotation_survey},
          {"tool_tip_link", errors.tool_tip_link},
          {"tool_tip_m", errors.tool_tip}};
}

}  // namespace edgefit
