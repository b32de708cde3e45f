// edgefit fit: fits the kinematic model to the scan (paper Sec. 5 robots,
// Sec. 6 conveyance systems) and writes result.json (DESIGN.md contract);
// optional outputs for the user.
//   edgefit fit --urdf=F [--attach=eef.urdf@link] --scan=F[,F...] --out=result.json
//               [--kind=auto|articulated|conveyance]
//               [--weighting=edge|uniform] [--w_high=10] [--loss=trivial] [--lambda=1]
//               [--init=x,y,yaw_deg] [--truth=T.json] [--out_joint_states=J.yaml]
//               [--out_urdf=U.urdf] [--out_ply=M.ply] [--out_report=R.html]
//               [--out_background=B.ptx|B.e57]
//               [--threads=N] [--seed=N]
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command_line.h"
#include "commands.h"
#include "common_flags.h"
#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/joint_states.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/model/calibrated_urdf.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/model/mesh_ply.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/pipeline/instance_crop.h"
#include "edgefit/pipeline/model_points.h"
#include "edgefit/pipeline/result_json.h"
#include "edgefit/report/fit_report.h"
#include "edgefit/scanner/truth.h"
#include "fit_flags.h"
#include "fit_result_file.h"

DEFINE_string(joint_states, "",
              "Known joints from a ROS joint_states YAML file (name and position lists, as "
              "--out_joint_states writes them): the model's independent joints named there are "
              "held at those values while the others are fitted; other names are ignored. With "
              "--joints, --joints wins for the joints it names.");
DEFINE_string(out_joint_states, "",
              "Optional output: joint values as YAML, ROS joint_states "
              "layout (name, position).");
DEFINE_string(out_urdf, "",
              "Optional output: the model with a world link and a fixed joint at "
              "the fitted base pose (joint values in a comment).");

DEFINE_string(out_background, "",
              "Optional output: the scan with the fitted model's points removed (.ptx, .pcd, "
              ".ply or .e57): the scanned equipment is replaced by its model.");
DEFINE_double(
    background_distance_mm, 8.0,
    "--out_background: points within this of the fitted model's surface are removed [mm].");

namespace edgefit::tools {
namespace {

using nlohmann::json;

// Per joint (model order) its verdict, "" for joints without one.
std::vector<std::string> JointVerdictNotes(const KinematicModel& model, const FitResult& fit) {
  std::vector<std::string> notes(model.joints().size());
  for (const BodyQuality& b : fit.bodies) {
    if (!b.joint.empty()) {
      notes[static_cast<size_t>(model.JointIndex(b.joint))] = JointVerdictName(b.verdict);
    }
  }
  return notes;
}

std::string FittedJointStates(const KinematicModel& model, const std::vector<double>& q,
                              const std::vector<std::string>& notes) {
  std::vector<std::pair<std::string, double>> values;
  std::string verdicts;
  for (size_t j = 0; j < model.joints().size(); ++j) {
    if (!model.joints()[j].IsMoving()) continue;
    values.emplace_back(model.joints()[j].name, q[j]);
    if (!notes[j].empty()) verdicts += " " + model.joints()[j].name + "=" + notes[j];
  }
  return JointStatesYaml(values, "edgefit fit: sensor_msgs/JointState (radians, metres)\nverdicts:" +
                                     verdicts + " (result.json joint_status)");
}

// --joint_states and --joints: the joints held at given values.
Status KnownJointsFromFlags(const KinematicModel& model, KnownJoints* known) {
  known->clear();
  KnownJoints from_file, from_flag;
  if (!FLAGS_joint_states.empty()) {
    EDGEFIT_RETURN_IF_ERROR(ReadJointStates(FLAGS_joint_states, &from_file));
  }
  EDGEFIT_RETURN_IF_ERROR(ParseNamedValues(FLAGS_joints, &from_flag));
  std::string ignored;
  for (const auto& [name, value] : from_file) {
    const int j = model.JointIndex(name);
    const bool named = std::any_of(from_flag.begin(), from_flag.end(),
                                   [&name](const auto& v) { return v.first == name; });
    if (j < 0 || !model.joints()[static_cast<size_t>(j)].IsIndependent()) {
      ignored += " " + name;
    } else if (!named) {
      known->emplace_back(name, value);
    }
  }
  if (!ignored.empty()) {
    Progress("--joint_states: not independent joints of the model, ignored:" + ignored);
  }
  known->insert(known->end(), from_flag.begin(), from_flag.end());
  return Status::Ok();
}

int RunFit(const Command& command) {
  if (FLAGS_urdf.empty()) return BadInput(command, "--urdf is required");
  if (FLAGS_scan.empty()) return BadInput(command, "--scan is required");
  if (FLAGS_out.empty()) return BadInput(command, "--out is required");
  if (!(FLAGS_background_distance_mm > 0.0)) {
    return BadInput(command, "--background_distance_mm must be > 0");
  }
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckFitFlags());  // before any file is read
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, CheckOutputPaths({FLAGS_out, FLAGS_out_joint_states, FLAGS_out_urdf, FLAGS_out_ply,
                                 FLAGS_out_report, FLAGS_out_background}));
  if (!FLAGS_out_report.empty()) {
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, CheckFitReportScripts(FitReportOptions()));
  }
  Eigen::AlignedBox3d roi;
  bool has_roi = false;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, RoiFromFlags(&roi, &has_roi));
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  const auto start = std::chrono::steady_clock::now();

  std::vector<AttachSpec> specs;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ParseAttachSpecList(FLAGS_attach, &specs));
  KinematicModel model;
  EDGEFIT_RETURN_IF_ERROR_EXIT(
      command, LoadModelWithAttachments(FLAGS_urdf, specs, ModelLoadOptions(), &model));
  AssetKind kind = AssetKind::kArticulated;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ChooseAssetKind(FLAGS_kind, model, &kind));
  FitOptions options;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, FitOptionsFromFlags(kind, &options));
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, KnownJointsFromFlags(model, &options.known_joints));
  ScanSet scans;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadScanList(FLAGS_scan, !FLAGS_out_background.empty(), &scans));
  std::vector<CellTruthAsset> truth;  // one asset, or a cell's (edgefit scan --scene)
  if (!FLAGS_truth.empty())
    EDGEFIT_RETURN_IF_ERROR_EXIT(command, ReadCellTruthJson(FLAGS_truth, &truth));
  const double load_seconds = SecondsSince(start);

  ScanSet in_roi;
  if (has_roi) {
    in_roi = CropToBox(scans, roi);
    if (in_roi.TotalValid() == 0) {
      return BadInput(command, Status::Error("--roi: the box holds none of the " +
                                             std::to_string(scans.TotalValid()) + " scan points"));
    }
    Progress("roi: " + std::to_string(in_roi.TotalValid()) + " of " + std::to_string(scans.TotalValid()) +
             " points in the box");
  }
  FitResult fit;
  EDGEFIT_RETURN_IF_ERROR_EXIT(command, Fit(model, has_roi ? in_roi : scans, options, &Progress, &fit));
  // Scored against the truth's one asset, or the cell's asset of this model
  // whose base is nearest the fitted one (within 0.5 m).
  const int scored_asset =
      truth.size() == 1 ? 0 : MatchTruthAsset(truth, {}, model, fit.T_world_base);
  FitErrors errors;
  if (scored_asset >= 0) {
    const Status status =
        ScoreFit(model, fit, truth[static_cast<size_t>(scored_asset)].truth, &errors);
    if (!status.ok()) return BadInput(command, status.WithContext(FLAGS_truth));
  }

  json result = FitResultJson(model, kind, options, fit);
  result["timing_s"]["load"] = load_seconds;
  result["inputs"] = FitInputsJson(FLAGS_urdf, specs, SplitList(FLAGS_scan), has_roi ? &roi : nullptr);
  if (scored_asset >= 0) {
    result["errors"] = FitErrorsJson(errors);
    if (truth.size() > 1) {
      result["errors"]["truth_asset"] = truth[static_cast<size_t>(scored_asset)].name;
    }
  }

  // Outputs: each atomic; a later failure removes the earlier ones.
  const std::vector<std::string> notes = JointVerdictNotes(model, fit);
  std::vector<std::string> written;
  auto fail = [&](const Status& status) {
    for (const std::string& path : written) std::remove(path.c_str());
    return BadInput(command, status);
  };
  if (!FLAGS_out_joint_states.empty()) {
    const Status status =
        WriteStringAtomically(FLAGS_out_joint_states, FittedJointStates(model, fit.q, notes));
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_joint_states);
  }
  if (!FLAGS_out_urdf.empty()) {
    std::string urdf;
    Status status = CalibratedUrdf(FLAGS_urdf, specs, model, fit.T_world_base, fit.q,
                                   ModelLoadOptions(), &urdf, notes);
    if (status.ok()) status = WriteStringAtomically(FLAGS_out_urdf, urdf);
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_urdf);
  }
  if (!FLAGS_out_ply.empty()) {
    const std::vector<Pose> T_world_link = model.ForwardKinematics(fit.q, fit.T_world_base);
    TriangleMesh mesh;
    for (size_t l = 0; l < model.links().size(); ++l) {
      mesh.Append(model.links()[l].mesh, T_world_link[l]);
    }
    const Status status = WriteMeshPly(
        FLAGS_out_ply, mesh, "edgefit fit: " + FLAGS_urdf + " at the fitted pose, world frame");
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_ply);
  }
  if (!FLAGS_out_report.empty()) {  // before the background takes the model's points away
    Progress("report: the scan against the fitted model");
    json shown = result;
    shown["timing_s"]["total"] = SecondsSince(start);
    std::vector<Pose> corrections;  // the stations as the fit registered them
    for (const StationCorrection& c : fit.stations.stations) corrections.push_back(c.correction);
    FitReportOptions report_options;
    report_options.edges = options.edges;  // the edge map as the fit's options find it
    const Status status =
        WriteFitReport(model, fit.q, fit.T_world_base, has_roi ? in_roi : scans, corrections,
                       shown, "edgefit fit: " + FLAGS_urdf, report_options, FLAGS_out_report,
                       &written);
    if (!status.ok()) return fail(status);
  }
  if (!FLAGS_out_background.empty()) {
    Progress("background: removing the fitted model's points");
    ModelPointsOptions background;
    background.distance = FLAGS_background_distance_mm * 1e-3;
    std::vector<std::vector<uint8_t>> marks;
    Status status = MarkModelPoints(scans, model, fit.q, fit.T_world_base, background, &marks);
    if (!status.ok()) return fail(status);
    const size_t before = scans.TotalValid();
    const size_t removed = RemoveMarkedPoints(marks, &scans);
    status = WriteScans(FLAGS_out_background, scans, WriteOptions());
    if (!status.ok()) return fail(status);
    written.push_back(FLAGS_out_background);
    result["background"] = {{"removed_points", removed},
                            {"kept_points", before - removed},
                            {"distance_m", background.distance}};
    std::printf("background: removed %zu of %zu points within %.1f mm of the fitted model\n",
                removed, before, FLAGS_background_distance_mm);
  }
  const double total = SecondsSince(start);
  result["timing_s"]["total"] = total;
  const Status status = WriteStringAtomically(FLAGS_out, result.dump(2) + "\n");
  if (!status.ok()) return fail(status);

  // Report on stdout.
  const Eigen::Vector3d rpy = RpyFromRotation(fit.T_world_base.linear());
  const Eigen::Vector3d xyz = fit.T_world_base.translation();
  std::printf("base: xyz %.4f %.4f %.4f m, rpy %.3f %.3f %.3f deg\n", xyz.x(), xyz.y(), xyz.z(),
              rpy.x() * 180.0 / M_PI, rpy.y() * 180.0 / M_PI, rpy.z() * 180.0 / M_PI);
  if (!FLAGS_truth.empty() && scored_asset < 0) {
    std::printf("truth: no asset of %s with this model's joints stands within 0.5 m of the "
                "fitted base: not scored\n",
                FLAGS_truth.c_str());
  }
  if (scored_asset < 0) {
    for (const int index : model.joint_order()) {  // parents first: base to tool
      const size_t j = static_cast<size_t>(index);
      const Joint& joint = model.joints()[j];
      if (!joint.IsMoving()) continue;
      const bool prismatic = joint.type == JointType::kPrismatic;
      const double scale = prismatic ? 1e3 : 180.0 / M_PI;
      char spread[48] = "";
      const std::vector<double>& stds = fit.chain_refinement.joint_std;  // none: not computed
      const double std = j < stds.size() && notes[j] != "unobservable" ? stds[j] : NAN;
      if (std::isfinite(std)) {
        std::snprintf(spread, sizeof(spread), "  (std %.4f)", std * scale);
      }
      std::printf("  %-24s %+10.4f %s%s\n", joint.name.c_str(), fit.q[j] * scale,
                  prismatic ? "mm " : "deg", spread);
    }
  } else {
    std::printf(
        "base error: %.3f mm, %.4f deg (in the survey's frame %.3f mm, %.4f deg); tool tip (%s) "
        "error: %.3f mm\n",
        errors.base_translation * 1e3, errors.base_rotation * 180.0 / M_PI,
        errors.base_translation_survey * 1e3, errors.base_rotation_survey * 180.0 / M_PI,
        errors.tool_tip_link.c_str(), errors.tool_tip * 1e3);
    std::printf("  %-24s %12s %12s %10s\n", "joint", "truth", "fit", "error");
    for (const JointError& j : errors.joints) {
      const double scale = j.prismatic ? 1e3 : 180.0 / M_PI;
      std::printf("  %-24s %12.4f %12.4f %10.4f %s%s%s\n", j.name.c_str(), j.truth * scale,
                  j.fit * scale, j.error * scale, j.prismatic ? "mm" : "deg",
                  j.independent ? "" : " (dependent)",
                  j.unobservable ? " (unobservable: a convention, not scored)" : "");
    }
  }
  std::string unobservable;  // named even when the fit is ok
  for (const BodyQuality& b : fit.bodies) {
    if (b.verdict == JointVerdict::kUnobservable) unobservable += " " + b.joint;
  }
  std::printf(
      "quality: %s%s%s%s%s\n", fit.ok ? "ok" : "NOT OK", fit.ok ? "" : ": ", fit.message.c_str(),
      unobservable.empty() ? "" : "; unobservable (no scan pins them, reported at their zero):",
      unobservable.c_str());
  std::printf(
      "time: edges %.2f s, base rough %.2f s, base precise %.2f s, chain %.2f s, stations "
      "%.2f s, %s %.2f s (of these, checking the alternatives %.2f s), mixed pixels %.2f s, "
      "total %.2f s (load %.2f s)\n",
      fit.timings.edges, fit.timings.base_rough, fit.timings.base_precise, fit.timings.chain,
      fit.timings.stations, options.refinement.chain.refine ? "refine" : "covariance",
      fit.timings.refine, fit.timings.alternatives, fit.timings.mixed_pixels, total, load_seconds);
  return kExitOk;
}

}  // namespace

Command FitCommand() {
  return {
      "fit",
      "fit the kinematic model to the scan: base pose and every joint (paper Sec. 5, 6)",
      "Usage:\n"
      "  edgefit fit --urdf=F [--attach=eef.urdf@link] --scan=F[,F...] --out=result.json\n"
      "              [--kind=auto|articulated|conveyance]\n"
      "              [--weighting=edge|uniform] [--w_high=10] [--loss=trivial] [--lambda=1]\n"
      "              [--parameterization=joint_space|pose_penalty] [--norefine_chain]\n"
      "              [--init=x,y,yaw_deg] [--roi=xmin,ymin,zmin,xmax,ymax,zmax]\n"
      "              [--truth=T.json] [--out_joint_states=J.yaml] [--out_urdf=U.urdf]\n"
      "              [--out_ply=M.ply] [--out_report=R.html] [--out_background=B.ptx]\n"
      "              [--background_distance_mm=8] [--threads=N] [--seed=N]\n"
      "Example:\n"
      "  edgefit fit --urdf=assets/robot/robot.urdf --attach=assets/robot/weld_gun.urdf@tool0 \\\n"
      "    --scan=robot.ptx --truth=robot_truth.json --out=result.json\n"
      "  edgefit fit --urdf=assets/conveyor/conveyor.urdf --scan=conveyor.ptx --out=result.json",
      WithFitOptionFlags({"urdf", "attach", "scan", "camera_info", "depth_scale", "joints",
                          "joint_states", "out", "kind", "init", "roi", "truth",
                          "out_joint_states", "out_urdf", "out_ply", "out_report", "out_background",
                          "background_distance_mm", "threads", "seed"}),
      &RunFit};
}

}  // namespace edgefit::tools
