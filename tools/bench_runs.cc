#include "bench_runs.h"

#include <cmath>
#include <sstream>

#include "edgefit/core/format.h"
#include "edgefit/pipeline/result_json.h"
#include "fit_flags.h"

namespace edgefit::tools {

std::string Number(double value) { return FormatNumber("%g", value); }

Status BenchFitOptions(AssetKind kind, const FitSetting& fit, uint64_t seed, FitOptions* options) {
  EDGEFIT_RETURN_IF_ERROR(FitOptionsFromFlags(kind, options));
  options->uniform_weights = fit.weighting == "uniform";
  options->edges.w_high = fit.w_high;
  options->seed = seed;
  options->residuals.loss = fit.loss;
  options->residuals.lambda = fit.lambda;
  for (WeightedIcpOptions* icp : {&options->base.icp, &options->chain.joint_icp,
                                  &options->chain.subtree_icp, &options->refinement.chain.icp}) {
    icp->correspondence.use_lattice = fit.search == "lattice";
  }
  options->chain.sweep.revolute_step = fit.sweep_step_deg * M_PI / 180.0;
  options->refinement.chain.refine = fit.refine_chain;
  return Status::Ok();
}

std::string Label(const Axes& axes, const ScanSetting& scan, const FitSetting& fit) {
  std::vector<std::string> parts;
  if (axes.sensor) parts.push_back("sensor=" + scan.sensor);
  if (axes.noise) parts.push_back("noise=" + Number(scan.noise_mm) + "mm");
  if (axes.spacing) parts.push_back("spacing=" + Number(scan.spacing_mm) + "mm");
  if (axes.scanners) parts.push_back("scanners=" + std::to_string(scan.scanners));
  if (axes.w_high) parts.push_back("w_high=" + Number(fit.w_high));
  if (axes.lambda) parts.push_back("lambda=" + Number(fit.lambda));
  if (axes.loss) parts.push_back("loss=" + fit.loss);
  if (axes.sweep_step) parts.push_back("sweep_step=" + Number(fit.sweep_step_deg) + "deg");
  if (axes.search) parts.push_back("search=" + fit.search);
  if (axes.refine) parts.push_back(fit.refine_chain ? "refine_chain" : "sequential");
  std::string label;
  for (const std::string& p : parts) label += (label.empty() ? "" : " ") + p;
  return label.empty() ? "-" : label;
}

namespace {
nlohmann::json Vector3Json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

nlohmann::json RunJson(const Run& run) {
  nlohmann::json joints = nlohmann::json::object(), prismatic = nlohmann::json::array(),
                 unobservable = nlohmann::json::object(), verdicts = nlohmann::json::object();
  nlohmann::json names = nlohmann::json::array();
  nlohmann::json stds = nlohmann::json::object(), residual_stds = nlohmann::json::object();
  const ChainRefinementSummary& chain = run.result.chain;
  for (const JointError& e : run.result.errors.joints) {
    if (!e.independent) continue;
    names.push_back(e.name);
    const size_t j = static_cast<size_t>(e.joint);
    if (j < chain.joint_std.size() && std::isfinite(chain.joint_std[j])) {
      stds[e.name] = chain.joint_std[j];
      residual_stds[e.name] = chain.joint_std_residuals[j];
    }
    (e.unobservable ? unobservable : joints)[e.name] = e.error;
    if (e.prismatic) prismatic.push_back(e.name);
  }
  for (const BodyQuality& b : run.result.bodies) {
    if (!b.joint.empty()) verdicts[b.joint] = JointVerdictName(b.verdict);
  }
  nlohmann::json timing = FitTimingsJson(run.result.timings);  // the fit's, without load
  timing["total"] = run.result.timings.total;
  return {{"asset", run.asset},
          {"posture", run.posture},
          {"accessories", run.scan.accessories},
          {"weighting", run.fit.weighting},
          {"label", run.label},
          {"settings",
           {{"noise_mm", run.scan.noise_mm},
            {"spacing_mm", run.scan.spacing_mm},
            {"scanners", run.scan.scanners},
            {"repeat", run.scan.repeat},
            {"sensor", run.scan.sensor},
            {"w_high", run.fit.w_high},
            {"lambda", run.fit.lambda},
            {"loss", run.fit.loss},
            {"sweep_step_deg", run.fit.sweep_step_deg},
            {"search", run.fit.search},
            {"refine_chain", run.fit.refine_chain}}},
          {"options", FitOptionsJson(run.options)},  // every fit option, as result.json's
          {"points", run.result.points},
          {"joint_names", names},  // the independent joints in the model's order
          {"joint_errors", joints},  // observable independent joints [rad] or [m]
          {"unobservable_joint_errors", unobservable},  // reported by convention
          {"joint_verdicts", verdicts},
          {"joint_std", stds},  // the fit's standard deviations, where computed
          {"joint_std_residuals", residual_stds},  // their residuals' part alone
          {"prismatic_joints", prismatic},
          {"base_translation_m", run.result.errors.base_translation},
          {"base_rotation_rad", run.result.errors.base_rotation},
          {"base_survey_translation_m", run.result.errors.base_translation_survey},
          {"base_survey_rotation_rad", run.result.errors.base_rotation_survey},
          // by world axis, to set against base_std
          {"base_survey_rotation_world_rad",
           Vector3Json(run.result.errors.base_rotation_survey_world)},
          {"base_survey_translation_world_m",
           Vector3Json(run.result.errors.base_translation_survey_world)},
          {"base_std", BaseStdJson(chain)},
          {"tool_tip_link", run.result.errors.tool_tip_link},
          {"tool_tip_m", run.result.errors.tool_tip},
          {"covariance_ok", run.result.chain.covariance_ok},
          {"timing_s", timing},
          {"ok", run.result.ok},
          {"message", run.result.message},
          {"failed", run.result.failed}};
}

std::string RunsCsv(const std::vector<Run>& runs) {
  std::ostringstream csv;
  csv << "asset,posture,accessories,weighting,noise_mm,scanners,repeat,w_high,lambda,loss,"
         "sweep_step_deg,search,refine_chain,joint,prismatic,truth,fit,error,ok,failed,"
         "spacing_mm\n";
  for (const Run& run : runs) {
    for (const JointError& e : run.result.errors.joints) {
      csv << run.asset << ',' << run.posture << ',' << run.scan.accessories << ','
          << run.fit.weighting << ',' << run.scan.noise_mm << ',' << run.scan.scanners << ','
          << run.scan.repeat << ',' << run.fit.w_high << ',' << run.fit.lambda << ','
          << run.fit.loss << ',' << run.fit.sweep_step_deg << ',' << run.fit.search << ','
          << run.fit.refine_chain << ',' << e.name << ',' << e.prismatic << ',' << e.truth << ','
          << e.fit << ',' << e.error << ',' << run.result.ok << ',' << run.result.failed << ','
          << run.scan.spacing_mm << '\n';
    }
  }
  return csv.str();
}

}  // namespace edgefit::tools
