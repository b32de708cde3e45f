#include "edgefit/bench/bench_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench_run_fields.h"
#include "edgefit/bench/ablation_charts.h"
#include "edgefit/bench/bench_case.h"
#include "edgefit/core/format.h"

namespace edgefit {
namespace {

using bench_run::IsPrismatic;
using bench_run::kNaN;
using bench_run::Number;
using bench_run::PoolErrors;
using bench_run::SettingText;
using nlohmann::json;

bool IsNumberOrNull(const json& v) { return v.is_number() || v.is_null(); }

// The independent joints of a run in the model's order (joint_names; files
// written before it have the keys' order), and whether each is prismatic.
std::vector<std::string> JointNames(const json& run) {
  std::vector<std::string> names;
  if (run.contains("joint_names")) {
    for (const json& n : run["joint_names"]) names.push_back(n.get<std::string>());
    return names;
  }
  for (const char* key : {"joint_errors", "unobservable_joint_errors"}) {
    for (const auto& item : run[key].items()) names.push_back(item.key());
  }
  return names;
}

// The error of `joint` in degrees or mm; *unobservable when the fit called
// it so; NaN when the run has none.
double JointError(const json& run, const std::string& joint, bool* unobservable) {
  const double scale = IsPrismatic(run, joint) ? 1e3 : 1.0 / kDeg;
  *unobservable = false;
  if (run["joint_errors"].contains(joint)) return scale * Number(run["joint_errors"], joint.c_str());
  if (run["unobservable_joint_errors"].contains(joint)) {
    *unobservable = true;
    return scale * Number(run["unobservable_joint_errors"], joint.c_str());
  }
  return kNaN;
}

std::string Verdict(const json& run) {
  return run["failed"].get<bool>() ? "FAILED" : (run["ok"].get<bool>() ? "ok" : "not ok");
}

// Whether any run carries a label (a setting other than scene and weights
// varies) and whether repeats vary.
bool Labelled(const json& runs) {
  for (const json& run : runs) {
    if (run["label"] != "-") return true;
  }
  return false;
}
bool Repeated(const json& runs) {
  std::set<std::string> repeats;
  for (const json& run : runs) repeats.insert(SettingText(run["settings"].value("repeat", json())));
  return repeats.size() > 1;
}

Table JointTable(const json& runs, const std::string& asset, bool prismatic, bool labelled) {
  Table table;
  std::vector<std::string> joints;
  for (const json& run : runs) {
    if (run["asset"] != asset) continue;
    for (const std::string& j : JointNames(run)) {
      if (IsPrismatic(run, j) == prismatic &&
          std::find(joints.begin(), joints.end(), j) == joints.end()) {
        joints.push_back(j);
      }
    }
  }
  if (joints.empty()) return table;
  table.caption = asset + (prismatic ? " (mm):" : " (degrees):");
  table.header = {"posture", "accessories", "weights"};
  if (labelled) table.header.push_back("settings");
  table.header.insert(table.header.end(), joints.begin(), joints.end());
  bool any_unobservable = false;
  for (const json& run : runs) {
    if (run["asset"] != asset) continue;
    std::vector<std::string> row = {run["posture"], run["accessories"], run["weighting"]};
    if (labelled) row.push_back(run["label"]);
    for (const std::string& j : joints) {
      bool unobservable = false;
      const double error = JointError(run, j, &unobservable);
      any_unobservable = any_unobservable || unobservable;
      row.push_back(!std::isfinite(error) ? "-"
                    : unobservable        ? "(" + FormatNumber("%.4f", error) + ")"
                                          : FormatNumber("%.4f", error));
    }
    table.rows.push_back(row);
  }
  if (any_unobservable) {
    table.note =
        "In brackets: joints the fit called unobservable (reported by convention, not scored).";
  }
  return table;
}

Table RunTable(const json& runs) {
  Table table;
  table.heading = "Base, tool tip and time per stage";
  table.header = {"asset",         "posture",    "accessories",  "weights",
                  "settings",      "points",     "base [mm]",    "base [deg]",
                  "in survey frame [mm, deg]",   "tool tip [mm]", "edges",
                  "base rough",    "base precise", "chain",      "refine",
                  "total",         "ok"};
  for (const json& run : runs) {
    const json& t = run["timing_s"];
    auto seconds = [&](const char* key) { return FormatNumber("%.2f s", Number(t, key)); };
    table.rows.push_back(
        {run["asset"], run["posture"], run["accessories"], run["weighting"], run["label"],
         FormatNumber("%.2f M", 1e-6 * Number(run, "points")),
         FormatNumber("%.3f", 1e3 * Number(run, "base_translation_m")),
         FormatNumber("%.4f", Number(run, "base_rotation_rad") / kDeg),
         FormatNumber("%.3f", 1e3 * Number(run, "base_survey_translation_m")) + ", " +
             FormatNumber("%.4f", Number(run, "base_survey_rotation_rad") / kDeg),
         FormatNumber("%.3f", 1e3 * Number(run, "tool_tip_m")), seconds("edges"), seconds("base_rough"),
         seconds("base_precise"), seconds("chain"), seconds("refine"), seconds("total"),
         Verdict(run)});
  }
  return table;
}

// "mean", "p95", "max" of `errors` with `format`, or dashes for none.
std::vector<std::string> StatsCells(const std::vector<double>& errors, const char* format) {
  if (errors.empty()) return {"-", "-", "-"};
  const ErrorStats stats = SummarizeErrors(errors);
  return {FormatNumber(format, stats.mean), FormatNumber(format, stats.p95), FormatNumber(format, stats.max)};
}

Table SummaryTable(const json& runs) {
  Table table;
  table.heading = "Per setting (postures and repeats pooled)";
  table.header = {"asset",          "accessories", "weights",       "settings",
                  "fits",           "revolute mean", "p95",         "max [deg]",
                  "prismatic mean", "p95",         "max [mm]",      "tool tip mean",
                  "p95 [mm]",       "base mean [mm]", "in survey frame", "failed",
                  "not ok",         "mean time [s]"};
  std::vector<std::string> keys;
  std::map<std::string, std::vector<const json*>> groups;
  for (const json& run : runs) {
    const std::string key = run["asset"].get<std::string>() + "|" +
                            run["accessories"].get<std::string>() + "|" +
                            run["weighting"].get<std::string>() + "|" +
                            run["label"].get<std::string>();
    if (groups.count(key) == 0) keys.push_back(key);
    groups[key].push_back(&run);
  }
  for (const std::string& key : keys) {
    const std::vector<const json*>& group = groups[key];
    std::vector<double> revolute, prismatic, tip, base, base_survey, time;
    int failed = 0, not_ok = 0;
    for (const json* run : group) {
      PoolErrors(*run, &revolute, &prismatic);
      tip.push_back(1e3 * Number(*run, "tool_tip_m"));
      base.push_back(1e3 * Number(*run, "base_translation_m"));
      base_survey.push_back(1e3 * Number(*run, "base_survey_translation_m"));
      time.push_back(Number((*run)["timing_s"], "total"));
      failed += (*run)["failed"].get<bool>();
      not_ok += !(*run)["ok"].get<bool>();
    }
    const json& first = *group.front();
    const double n = static_cast<double>(group.size());
    std::vector<std::string> row = {first["asset"], first["accessories"], first["weighting"],
                                    first["label"], std::to_string(group.size())};
    for (const std::string& cell : StatsCells(revolute, "%.4f")) row.push_back(cell);
    for (const std::string& cell : StatsCells(prismatic, "%.3f")) row.push_back(cell);
    const ErrorStats t = SummarizeErrors(tip);
    row.insert(row.end(), {FormatNumber("%.3f", t.mean), FormatNumber("%.3f", t.p95),
                           FormatNumber("%.3f", SummarizeErrors(base).mean),
                           FormatNumber("%.3f", SummarizeErrors(base_survey).mean),
                           FormatNumber("%.0f%%", 100.0 * failed / n),
                           FormatNumber("%.0f%%", 100.0 * not_ok / n),
                           FormatNumber("%.1f", SummarizeErrors(time).mean)});
    table.rows.push_back(row);
  }
  return table;
}

}  // namespace

Status CheckBenchRuns(const json& runs) {
  if (!runs.is_array() || runs.empty()) {
    return Status::Error("not the runs of edgefit bench --out_json (a non-empty JSON array)");
  }
  for (size_t k = 0; k < runs.size(); ++k) {
    const json& run = runs[k];
    auto fail = [k](const std::string& what) {
      return Status::Error("run " + std::to_string(k + 1) + ": " + what);
    };
    if (!run.is_object()) return fail("not an object");
    for (const char* key : {"asset", "posture", "accessories", "weighting", "label"}) {
      if (!run.contains(key) || !run[key].is_string()) return fail(std::string(key) + " missing");
    }
    for (const char* key : {"points", "base_translation_m", "base_rotation_rad",
                            "base_survey_translation_m", "base_survey_rotation_rad", "tool_tip_m"}) {
      if (!run.contains(key) || !IsNumberOrNull(run[key])) return fail(std::string(key) + " missing");
    }
    for (const char* key : {"ok", "failed"}) {
      if (!run.contains(key) || !run[key].is_boolean()) return fail(std::string(key) + " missing");
    }
    for (const char* key : {"settings", "joint_errors", "unobservable_joint_errors", "timing_s"}) {
      if (!run.contains(key) || !run[key].is_object()) return fail(std::string(key) + " missing");
    }
    for (const char* key : {"joint_errors", "unobservable_joint_errors"}) {
      for (const auto& item : run[key].items()) {
        if (!IsNumberOrNull(item.value())) return fail(std::string(key) + " holds a non-number");
      }
    }
    for (const char* key : {"edges", "base_rough", "base_precise", "chain", "refine", "total"}) {
      if (!run["timing_s"].contains(key) || !IsNumberOrNull(run["timing_s"][key])) {
        return fail(std::string("timing_s.") + key + " missing");
      }
    }
    if (!run.contains("prismatic_joints") || !run["prismatic_joints"].is_array()) {
      return fail("prismatic_joints missing");
    }
    if (run.contains("joint_names")) {
      if (!run["joint_names"].is_array()) return fail("joint_names is not an array");
      for (const json& n : run["joint_names"]) {
        if (!n.is_string()) return fail("joint_names holds a non-string");
      }
    }
  }
  return Status::Ok();
}

std::vector<Table> BenchTables(const json& runs) {
  std::vector<std::string> assets;
  for (const json& run : runs) {
    if (std::find(assets.begin(), assets.end(), run["asset"]) == assets.end()) {
      assets.push_back(run["asset"]);
    }
  }
  const bool labelled = Labelled(runs);
  std::vector<Table> tables;
  for (const bool prismatic : {false, true}) {
    Table heading;
    heading.heading = prismatic ? "Table 2: translation error per joint [mm]"
                                : "Table 1: rotation error per joint [deg]";
    std::vector<Table> per_asset;
    for (const std::string& asset : assets) {
      Table table = JointTable(runs, asset, prismatic, labelled);
      if (!table.header.empty()) per_asset.push_back(table);
    }
    if (per_asset.empty()) {
      heading.note = prismatic ? "No prismatic joints in these assets."
                               : "No revolute joints in these assets.";
    }
    tables.push_back(heading);
    tables.insert(tables.end(), per_asset.begin(), per_asset.end());
  }
  tables.push_back(RunTable(runs));
  if (labelled || Repeated(runs)) tables.push_back(SummaryTable(runs));
  return tables;
}

TablesReport BenchReport(const json& runs, const std::string& command) {
  TablesReport report;
  report.title = "edgefit bench";
  int failed = 0, not_ok = 0;
  for (const json& run : runs) {
    failed += run["failed"].get<bool>();
    not_ok += !run["ok"].get<bool>();
  }
  report.lines.push_back(std::to_string(runs.size()) + " fits: " + std::to_string(failed) +
                         " failed (a revolute joint off by more than 0.5 deg or a prismatic one "
                         "by more than 5 mm), " + std::to_string(not_ok) + " said not ok.");
  if (!command.empty()) report.lines.push_back("Made by: " + command);
  report.charts_heading = "Ablation plots";
  report.charts = AblationCharts(runs);
  report.tables = BenchTables(runs);
  return report;
}

}  // namespace edgefit
