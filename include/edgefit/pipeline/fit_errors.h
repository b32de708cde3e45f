// A fit scored against the virtual scanner's ground truth (paper Sec. 7.3):
// per-joint errors, base pose errors and the failed-fit rule of the issue
// bar (any joint off by more than the failure threshold).
#ifndef EDGEFIT_PIPELINE_FIT_ERRORS_H_
#define EDGEFIT_PIPELINE_FIT_ERRORS_H_

#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

struct JointError {
  std::string name;
  bool prismatic = false;
  bool independent = true;  // false: mimic or loop-closure joint
  double truth = 0.0;       // [rad] or [m]
  double fit = 0.0;
  double error = 0.0;       // |fit - truth| [rad] (modulo a turn) or [m]
};

struct FitErrors {
  std::vector<JointError> joints;  // every non-fixed joint, model order
  double base_translation = 0.0;   // [m]
  double base_rotation = 0.0;      // [rad]
};

// truth_joints: name -> value of every non-fixed joint (Truth::joints).
// Fails when a joint of the model is missing from the truth.
Status CompareWithTruth(const KinematicModel& model, const std::vector<double>& q_fit,
                        const Pose& T_world_base_fit,
                        const std::vector<std::pair<std::string, double>>& truth_joints,
                        const Pose& T_world_base_truth, FitErrors* errors);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_FIT_ERRORS_H_
