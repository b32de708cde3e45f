#include "edgefit/bench/ablation_charts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bench_run_fields.h"
#include "edgefit/bench/bench_case.h"

namespace edgefit {
namespace {

using bench_run::kNaN;
using bench_run::PoolErrors;
using bench_run::SettingText;
using nlohmann::json;

// An ablation axis: its key in a run's "settings", how the plots name it,
// whether its values are names rather than numbers.
struct AblationAxis {
  const char* key;
  const char* name;
  bool categorical;
};
constexpr AblationAxis kAxes[] = {
    {"w_high", "w_high (Eq. 6)", false},
    {"lambda", "lambda (Eq. 10/14)", false},
    {"loss", "loss of the precise stages", true},
    {"sweep_step_deg", "sweep step [deg]", false},
    {"search", "correspondence search", true},
    {"refine_chain", "whole-chain refinement", true},
    {"noise_mm", "range noise sigma [mm]", false},
    {"scanners", "scanners", false},
    {"sensor", "sensor", true},
    {"spacing_mm", "scan spacing [mm]", false},
};

// The axes whose values differ between the runs.
std::vector<const AblationAxis*> VariedAxes(const json& runs) {
  std::vector<const AblationAxis*> varied;
  for (const AblationAxis& axis : kAxes) {
    std::set<std::string> values;
    for (const json& run : runs) values.insert(SettingText(run["settings"].value(axis.key, json())));
    if (values.size() > 1) varied.push_back(&axis);
  }
  return varied;
}

// Mean error against one axis: a series per (asset, scene, weights, the
// other axes' values); `prismatic`: prismatic joints in mm, else revolute
// in degrees. An empty chart when no run has such joints.
Chart AxisChart(const json& runs, const AblationAxis& axis,
                const std::vector<const AblationAxis*>& varied, bool prismatic) {
  Chart chart;
  chart.title = std::string(prismatic ? "prismatic" : "revolute") + " joints: mean error against " +
                axis.name;
  chart.x_label = axis.name;
  chart.y_label = prismatic ? "mean error [mm]" : "mean error [deg]";
  // The axis' values, in order (numbers sorted, names as they first came).
  std::vector<std::string> values;
  std::vector<double> numbers;
  for (const json& run : runs) {
    const json& v = run["settings"].value(axis.key, json());
    const std::string text = SettingText(v);
    if (std::find(values.begin(), values.end(), text) != values.end()) continue;
    values.push_back(text);
    numbers.push_back(v.is_number() ? v.get<double>() : kNaN);
  }
  if (!axis.categorical) {
    std::vector<size_t> order(values.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return numbers[a] < numbers[b]; });
    std::vector<std::string> v2;
    std::vector<double> n2;
    for (const size_t k : order) v2.push_back(values[k]), n2.push_back(numbers[k]);
    values = v2;
    numbers = n2;
    chart.log_x = numbers.front() > 0.0 && numbers.back() / numbers.front() >= 10.0;
  } else {
    chart.categories = values;
  }
  std::vector<std::string> series_keys;
  std::map<std::string, std::vector<std::vector<double>>> pooled;  // key -> per value
  for (const json& run : runs) {
    std::string key = run["asset"].get<std::string>() + ", " +
                      run["accessories"].get<std::string>() + " accessories, " +
                      run["weighting"].get<std::string>() + " weights";
    for (const AblationAxis* other : varied) {
      if (other != &axis) key += ", " + std::string(other->key) + "=" +
                                 SettingText(run["settings"].value(other->key, json()));
    }
    if (pooled.count(key) == 0) {
      series_keys.push_back(key);
      pooled[key].resize(values.size());
    }
    const size_t k = static_cast<size_t>(
        std::find(values.begin(), values.end(), SettingText(run["settings"].value(axis.key, json()))) -
        values.begin());
    std::vector<double> revolute, prismatic_errors;
    PoolErrors(run, &revolute, &prismatic_errors);
    const std::vector<double>& errors = prismatic ? prismatic_errors : revolute;
    pooled[key][k].insert(pooled[key][k].end(), errors.begin(), errors.end());
  }
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const std::string& key : series_keys) {
    ChartSeries series;
    series.name = key;
    bool any = false;
    for (size_t k = 0; k < values.size(); ++k) {
      series.x.push_back(axis.categorical ? static_cast<double>(k) : numbers[k]);
      const std::vector<double>& errors = pooled[key][k];
      const double mean = errors.empty() ? kNaN : SummarizeErrors(errors).mean;
      series.y.push_back(mean);
      if (std::isfinite(mean)) {
        any = true;
        if (mean > 0.0) lo = std::min(lo, mean);
        hi = std::max(hi, mean);
      }
    }
    if (any) chart.series.push_back(series);
  }
  chart.log_y = std::isfinite(lo) && hi / lo >= 20.0;
  return chart;
}

}  // namespace

std::vector<Chart> AblationCharts(const json& runs) {
  std::vector<Chart> charts;
  const std::vector<const AblationAxis*> varied = VariedAxes(runs);
  for (const AblationAxis* axis : varied) {
    for (const bool prismatic : {false, true}) {
      Chart chart = AxisChart(runs, *axis, varied, prismatic);
      if (!chart.series.empty()) charts.push_back(chart);
    }
  }
  return charts;
}

}  // namespace edgefit
