// The runs of `edgefit bench` and their report: Tables 1 and 2 (error
// per joint), base and time per stage, the summary per setting, the JSON
// of a run.
#ifndef EDGEFIT_TOOLS_BENCH_REPORT_H_
#define EDGEFIT_TOOLS_BENCH_REPORT_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "edgefit/bench/bench_case.h"

namespace edgefit::tools {

// A scan of the product of the scan axes.
struct ScanSetting {
  std::string accessories;  // "without" / "with"
  double noise_mm = 1.0;
  int scanners = 3;
  int repeat = 0;
  std::string sensor = "ideal";  // edgefit scan --sensor
};

// A fit of the product of the fit axes.
struct FitSetting {
  std::string weighting;
  double w_high = 10.0;
  double lambda = 1.0;
  std::string loss;
  double sweep_step_deg = 1.0;
  std::string search;
  bool refine_chain = false;
};

struct Run {
  std::string asset, posture;
  ScanSetting scan;
  FitSetting fit;
  std::string label;  // the varied settings, e.g. "w_high=5"
  BenchResult result;
};

// The axes given more than one value, for the labels.
struct Axes {
  bool noise = false, scanners = false, repeat = false, sensor = false;
  bool w_high = false, lambda = false, loss = false, sweep_step = false, search = false,
       refine = false;
};

// "%g" of value.
std::string Number(double value);
// The varied settings of a run, e.g. "w_high=5" ("-" when none varies).
std::string Label(const Axes& axes, const ScanSetting& scan, const FitSetting& fit);

// Table 1 (prismatic false: revolute joints, degrees) or Table 2 (prismatic
// joints, mm) for one asset: a row per run, a column per joint.
void PrintJointTable(const std::vector<Run>& runs, const std::string& asset, bool prismatic,
                     bool labelled);
// A row per run: base (against the truth and in the survey's frame), tool
// tip, time per stage, verdict.
void PrintRunTable(const std::vector<Run>& runs);
// Per setting: mean, p95 and max per joint kind, tool tip, failure and
// not-ok rates, time.
void PrintSummary(const std::vector<Run>& runs);
nlohmann::json RunJson(const Run& run);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_BENCH_REPORT_H_
