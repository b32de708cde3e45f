// The runs of `edgefit bench`: their settings, labels and JSON (from which
// bench_tables.h makes the tables and plots).
#ifndef EDGEFIT_TOOLS_BENCH_RUNS_H_
#define EDGEFIT_TOOLS_BENCH_RUNS_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "edgefit/bench/bench_case.h"
#include "edgefit/core/status.h"
#include "edgefit/pipeline/asset_kind.h"
#include "edgefit/pipeline/fit_options.h"

namespace edgefit::tools {

// A scan of the product of the scan axes.
struct ScanSetting {
  std::string accessories;  // "without" / "with"
  double noise_mm = 1.0;
  double spacing_mm = 1.7;
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
  std::string label;   // the varied settings, e.g. "w_high=5"
  FitOptions options;  // as fitted: the axes over the fit flags
  BenchResult result;
};

// The axes given more than one value, for the labels.
struct Axes {
  bool noise = false, spacing = false, scanners = false, repeat = false, sensor = false;
  bool w_high = false, lambda = false, loss = false, sweep_step = false, search = false,
       refine = false;
};

// "%g" of value.
std::string Number(double value);
// The varied settings of a run, e.g. "w_high=5" ("-" when none varies).
std::string Label(const Axes& axes, const ScanSetting& scan, const FitSetting& fit);

// The fit flags' options (fit_flags.h) with the setting's axes over them.
Status BenchFitOptions(AssetKind kind, const FitSetting& fit, uint64_t seed, FitOptions* options);

// One CSV line per fitted joint of every run (edgefit bench --out_csv).
std::string RunsCsv(const std::vector<Run>& runs);

// The run as an object of the JSON array of `edgefit bench --out_json`
// (bench_tables.h reads it).
nlohmann::json RunJson(const Run& run);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_BENCH_RUNS_H_
