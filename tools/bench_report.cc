#include "bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace edgefit::tools {
namespace {

constexpr double kDeg = M_PI / 180.0;

}  // namespace

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

std::string Label(const Axes& axes, const ScanSetting& scan, const FitSetting& fit) {
  std::vector<std::string> parts;
  if (axes.sensor) parts.push_back("sensor=" + scan.sensor);
  if (axes.noise) parts.push_back("noise=" + Number(scan.noise_mm) + "mm");
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

// Table 1 or 2 for one asset: a row per run, a column per joint of the kind.
void PrintJointTable(const std::vector<Run>& runs, const std::string& asset, bool prismatic,
                     bool labelled) {
  std::vector<std::string> joints;
  for (const Run& run : runs) {
    if (run.asset != asset) continue;
    for (const JointError& e : run.result.errors.joints) {
      if (e.independent && e.prismatic == prismatic &&
          std::find(joints.begin(), joints.end(), e.name) == joints.end()) {
        joints.push_back(e.name);
      }
    }
  }
  if (joints.empty()) return;
  bool unobservable = false;
  std::printf("\n%s (%s):\n\n| posture | accessories | weights |%s", asset.c_str(),
              prismatic ? "mm" : "degrees", labelled ? " settings |" : "");
  for (const std::string& j : joints) std::printf(" %s |", j.c_str());
  std::printf("\n|---|---|---|%s", labelled ? "---|" : "");
  for (size_t k = 0; k < joints.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (const Run& run : runs) {
    if (run.asset != asset) continue;
    std::printf("| %s | %s | %s |", run.posture.c_str(), run.scan.accessories.c_str(),
                run.fit.weighting.c_str());
    if (labelled) std::printf(" %s |", run.label.c_str());
    for (const std::string& j : joints) {
      for (const JointError& e : run.result.errors.joints) {
        if (e.name != j) continue;
        const double error = prismatic ? 1e3 * e.error : e.error / kDeg;
        std::printf(e.unobservable ? " (%.4f) |" : " %.4f |", error);
        unobservable = unobservable || e.unobservable;
      }
    }
    std::printf("\n");
  }
  if (unobservable) {
    std::printf("\nIn brackets: joints the fit called unobservable (reported by convention, not "
                "scored).\n");
  }
}

namespace {

// "mean | p95 | max" of the errors with `format`, or dashes for none.
std::string StatsCells(const std::vector<double>& errors, const char* format) {
  if (errors.empty()) return "- | - | -";
  const ErrorStats stats = SummarizeErrors(errors);
  std::string cells;
  for (const double v : {stats.mean, stats.p95, stats.max}) {
    char cell[32];
    std::snprintf(cell, sizeof(cell), format, v);
    cells += (cells.empty() ? "" : " | ") + std::string(cell);
  }
  return cells;
}

}  // namespace

void PrintRunTable(const std::vector<Run>& runs) {
  std::printf(
      "\n## Base, tool tip and time per stage\n\n| asset | posture | accessories | weights | "
      "settings | points | base [mm] | base [deg] | in survey frame [mm, deg] | tool tip [mm] | "
      "edges | base rough | base precise | chain | refine | total | ok |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Run& run : runs) {
    const BenchResult& r = run.result;
    std::printf(
        "| %s | %s | %s | %s | %s | %.2f M | %.3f | %.4f | %.3f, %.4f | %.3f | %.2f s | %.2f s | "
        "%.2f s | %.2f s | %.2f s | %.2f s | %s |\n",
        run.asset.c_str(), run.posture.c_str(), run.scan.accessories.c_str(),
        run.fit.weighting.c_str(), run.label.c_str(), 1e-6 * static_cast<double>(r.points),
        1e3 * r.errors.base_translation, r.errors.base_rotation / kDeg,
        1e3 * r.errors.base_translation_survey, r.errors.base_rotation_survey / kDeg,
        1e3 * r.errors.tool_tip, r.timings.edges, r.timings.base_rough, r.timings.base_precise,
        r.timings.chain, r.timings.refine, r.timings.total,
        r.failed ? "FAILED" : (r.ok ? "ok" : "not ok"));
  }
}

// One row per (asset, accessories, weights, settings): the errors of all its
// runs (postures, repeats) pooled.
void PrintSummary(const std::vector<Run>& runs) {
  std::vector<std::string> keys;
  std::map<std::string, std::vector<const Run*>> groups;
  for (const Run& run : runs) {
    const std::string key =
        run.asset + " | " + run.scan.accessories + " | " + run.fit.weighting + " | " + run.label;
    if (groups.count(key) == 0) keys.push_back(key);
    groups[key].push_back(&run);
  }
  std::printf(
      "\n## Per setting (postures and repeats pooled)\n\n| asset | accessories | weights | "
      "settings | fits | revolute mean | p95 | max [deg] | prismatic mean | p95 | max [mm] | "
      "tool tip mean | p95 [mm] | base mean [mm] | in survey frame | failed | not ok | mean time "
      "[s] |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& key : keys) {
    std::vector<double> revolute, prismatic, tip, base, base_survey, time;
    int failed = 0, not_ok = 0;
    for (const Run* run : groups[key]) {
      const BenchResult& r = run->result;
      for (const JointError& e : r.errors.joints) {
        if (!e.independent || e.unobservable) continue;
        (e.prismatic ? prismatic : revolute)
            .push_back(e.prismatic ? 1e3 * e.error : e.error / kDeg);
      }
      tip.push_back(1e3 * r.errors.tool_tip);
      base.push_back(1e3 * r.errors.base_translation);
      base_survey.push_back(1e3 * r.errors.base_translation_survey);
      time.push_back(r.timings.total);
      failed += r.failed;
      not_ok += !r.ok;
    }
    const ErrorStats t = SummarizeErrors(tip);
    const size_t n = groups[key].size();
    std::printf("| %s | %zu | %s | %s | %.3f | %.3f | %.3f | %.3f | %.0f%% | %.0f%% | %.1f |\n",
                key.c_str(), n, StatsCells(revolute, "%.4f").c_str(),
                StatsCells(prismatic, "%.3f").c_str(), t.mean, t.p95, SummarizeErrors(base).mean,
                SummarizeErrors(base_survey).mean, 100.0 * failed / static_cast<double>(n),
                100.0 * not_ok / static_cast<double>(n), SummarizeErrors(time).mean);
  }
}

nlohmann::json RunJson(const Run& run) {
  nlohmann::json joints = nlohmann::json::object(), prismatic = nlohmann::json::array(),
                 unobservable = nlohmann::json::object(), verdicts = nlohmann::json::object();
  for (const JointError& e : run.result.errors.joints) {
    if (!e.independent) continue;
    (e.unobservable ? unobservable : joints)[e.name] = e.error;
    if (e.prismatic) prismatic.push_back(e.name);
  }
  for (const BodyQuality& b : run.result.bodies) {
    if (!b.joint.empty()) verdicts[b.joint] = JointVerdictName(b.verdict);
  }
  const FitTimings& t = run.result.timings;
  return {{"asset", run.asset},
          {"posture", run.posture},
          {"accessories", run.scan.accessories},
          {"weighting", run.fit.weighting},
          {"label", run.label},
          {"settings",
           {{"noise_mm", run.scan.noise_mm},
            {"scanners", run.scan.scanners},
            {"repeat", run.scan.repeat},
            {"sensor", run.scan.sensor},
            {"w_high", run.fit.w_high},
            {"lambda", run.fit.lambda},
            {"loss", run.fit.loss},
            {"sweep_step_deg", run.fit.sweep_step_deg},
            {"search", run.fit.search},
            {"refine_chain", run.fit.refine_chain}}},
          {"points", run.result.points},
          {"joint_errors", joints},  // observable independent joints [rad] or [m]
          {"unobservable_joint_errors", unobservable},  // reported by convention
          {"joint_verdicts", verdicts},
          {"prismatic_joints", prismatic},
          {"base_translation_m", run.result.errors.base_translation},
          {"base_rotation_rad", run.result.errors.base_rotation},
          {"base_survey_translation_m", run.result.errors.base_translation_survey},
          {"base_survey_rotation_rad", run.result.errors.base_rotation_survey},
          {"tool_tip_link", run.result.errors.tool_tip_link},
          {"tool_tip_m", run.result.errors.tool_tip},
          {"covariance_ok", run.result.chain.covariance_ok},
          {"timing_s",
           {{"edges", t.edges},
            {"base_rough", t.base_rough},
            {"base_precise", t.base_precise},
            {"chain", t.chain},
            {"refine", t.refine},
            {"alternatives", t.alternatives},
            {"total", t.total}}},
          {"ok", run.result.ok},
          {"message", run.result.message},
          {"failed", run.result.failed}};
}

}  // namespace edgefit::tools
