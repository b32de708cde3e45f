// The bench's ablation plots (paper Sec. 7.4 and this project's axes),
// made from its runs (the JSON array of `edgefit bench --out_json`, checked
// by CheckBenchRuns).
#ifndef EDGEFIT_BENCH_ABLATION_CHARTS_H_
#define EDGEFIT_BENCH_ABLATION_CHARTS_H_

#include <vector>

#include <nlohmann/json.hpp>

#include "edgefit/report/chart.h"

namespace edgefit {

// Per ablation axis with more than one value (w_high, lambda, loss, sweep
// step, search, refinement, noise, scanners, sensor, spacing): the mean
// error of the observable revolute joints [deg], and of the prismatic ones
// [mm], against the axis; a line per asset, scene, weighting and the other
// axes' values; postures and repeats pooled.
std::vector<Chart> AblationCharts(const nlohmann::json& runs);

}  // namespace edgefit

#endif  // EDGEFIT_BENCH_ABLATION_CHARTS_H_
