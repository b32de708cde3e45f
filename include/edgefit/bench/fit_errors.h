// A fit scored against the virtual scanner's ground truth (paper Sec. 7.3):
// per-joint errors, base pose errors and the failed-fit rule (any joint off
// by more than the failure threshold).
#ifndef EDGEFIT_BENCH_FIT_ERRORS_H_
#define EDGEFIT_BENCH_FIT_ERRORS_H_

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/fit_result.h"
#include "edgefit/scanner/truth.h"

namespace edgefit {

struct JointError {
  std::string name;
  int joint = -1;  // index in model.joints()
  bool prismatic = false;
  bool independent = true;  // false: mimic or loop-closure joint
  double truth = 0.0;       // [rad] or [m]
  double fit = 0.0;
  double error = 0.0;  // |fit - truth| [rad] (modulo a turn) or [m]
  // The fit said no scan could pin it (JointVerdict::kUnobservable): its
  // value is a convention, left out of the accuracy figures and of the
  // failed-fit rule.
  bool unobservable = false;
};

struct FitErrors {
  std::vector<JointError> joints;  // every non-fixed joint, model order
  double base_translation = 0.0;   // [m]
  double base_rotation = 0.0;      // [rad]
  // The base against the truth moved into the survey's frame (SurveyFrame):
  // what a scan whose stations carry registration residuals can tell. The
  // same as above when the stations are exact.
  double base_translation_survey = 0.0;  // [m]
  double base_rotation_survey = 0.0;     // [rad]
  // The same error by world axis, as the fit's base_std gives it: the
  // rotation vector of R_fit R_truth^T [rad] and t_fit - t_truth [m].
  Eigen::Vector3d base_rotation_survey_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d base_translation_survey_world = Eigen::Vector3d::Zero();
  // The tool tip (ToolTipLink): its origin's distance from where the
  // truth puts it [m], base and every joint error together.
  std::string tool_tip_link;
  double tool_tip = 0.0;
};

// The tool tip: the end of the arm, where a process happens. The link with
// the most revolute joints between it and the root, ties going to the one
// with the most fixed joints (a TCP frame below the flange), then to the
// first in model order. Prismatic joints do not count: a gun's moving jaw
// is not its TCP. The bundled robot with its gun: `tcp`; without: `tool0`.
int ToolTipLink(const KinematicModel& model);

// The survey's frame: where a multi-station survey puts the world when each
// station's pose was written with a registration residual, T_survey_world =
// the mean of the stations' T_written * T_true^-1 (rotation vectors and
// translations averaged: first order in residuals of millimetres and
// hundredths of a degree). A scan of the stations alone cannot tell it from
// the true world: the fit's station alignment keeps the stations' mean
// (station_alignment.h), so a base up to that mean off the truth is as close
// as the scan allows. Identity for exact stations, or lists that differ in
// size.
Pose SurveyFrame(const std::vector<Pose>& T_world_scanners_true,
                 const std::vector<Pose>& T_survey_scanners_written);

// truth_joints: name -> value of every non-fixed joint (Truth::joints).
// T_survey_world: SurveyFrame of the scan's stations (base_*_survey).
// symmetry: the fit's FitResult::base_symmetry; the truth is compared in
// the placement among those it allows whose joint is nearest the fit's
// (the same geometry). Fails when a joint of the model is missing from the truth.
Status CompareWithTruth(const KinematicModel& model, const std::vector<double>& q_fit,
                        const Pose& T_world_base_fit,
                        const std::vector<std::pair<std::string, double>>& truth_joints,
                        const Pose& T_world_base_truth, const Pose& T_survey_world,
                        FitErrors* errors, const BaseSymmetry& symmetry = BaseSymmetry());

// The asset of a cell's truth a fit of `model` with base T_world_base is
// scored against: the one whose base is nearest (within max_distance [m]),
// not taken yet (taken: one flag per asset, or empty) and with every joint
// its truth names in the model; -1 when none.
int MatchTruthAsset(const std::vector<CellTruthAsset>& truth, const std::vector<bool>& taken,
                    const KinematicModel& model, const Pose& T_world_base,
                    double max_distance = 0.5);

// Sets JointError::unobservable from the fit's verdicts (FitResult::bodies).
void MarkUnobservableJoints(const std::vector<BodyQuality>& bodies, FitErrors* errors);

// A fit scored against its truth asset (edgefit fit and edgefit cell with
// --truth): CompareWithTruth in the survey's frame of the truth's stations,
// then MarkUnobservableJoints.
Status ScoreFit(const KinematicModel& model, const FitResult& fit, const Truth& truth,
                FitErrors* errors);

// result.json's `errors` (docs/result_json.md): `joints` (name -> error),
// the base's errors against the truth and in the survey's frame, the tool
// tip's.
nlohmann::json FitErrorsJson(const FitErrors& errors);

}  // namespace edgefit

#endif  // EDGEFIT_BENCH_FIT_ERRORS_H_
