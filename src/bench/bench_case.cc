#include "edgefit/bench/bench_case.h"

#include <algorithm>
#include <cmath>

#include "edgefit/core/split_mix64.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/scanner/truth.h"

namespace edgefit {

BenchCase MakeBenchCase(const std::string& name, uint64_t seed, uint64_t stream,
                        double base_range) {
  BenchCase c;
  c.name = name;
  c.seed = SplitMix64::StreamSeed(seed, stream);
  SplitMix64 random(c.seed);
  const double x = random.Uniform(-base_range, base_range);
  const double y = random.Uniform(-base_range, base_range);
  c.T_world_base = PoseFromXyYaw(x, y, random.Uniform(-M_PI, M_PI));
  return c;
}

Status NamedPostureCases(const KinematicModel& model, const std::string& postures_file,
                         uint64_t seed, double base_range, std::vector<BenchCase>* cases) {
  std::vector<std::string> names;
  EDGEFIT_RETURN_IF_ERROR(ListPostures(postures_file, &names));
  for (size_t i = 0; i < names.size(); ++i) {
    BenchCase c = MakeBenchCase(names[i], seed, i, base_range);
    c.q = model.ZeroJoints();
    EDGEFIT_RETURN_IF_ERROR(LoadNamedPosture(postures_file, names[i], model, &c.q));
    EDGEFIT_RETURN_IF_ERROR(model.ResolveDependentJoints(&c.q));
    cases->push_back(std::move(c));
  }
  return Status::Ok();
}

Status ScanBenchCase(const KinematicModel& model, const BenchCase& bench_case,
                     AssetScanOptions scan_options, VirtualScan* scan) {
  scan_options.seed = bench_case.seed;
  return ScanAsset(model, bench_case.q, bench_case.T_world_base, scan_options, scan, nullptr);
}

Status FitBenchCase(const KinematicModel& model, const BenchCase& bench_case, const ScanSet& scans,
                    const FitOptions& fit_options, BenchResult* result,
                    const ProgressFn& progress) {
  *result = BenchResult();
  result->points = scans.TotalValid();
  FitResult fit;
  EDGEFIT_RETURN_IF_ERROR(Fit(model, scans, fit_options, progress, &fit));
  result->timings = fit.timings;
  result->bodies = fit.bodies;
  result->chain = fit.chain_refinement;
  result->ok = fit.ok;
  result->message = fit.message;
  EDGEFIT_RETURN_IF_ERROR(CompareWithTruth(model, fit.q, fit.T_world_base,
                                           NamedJointValues(model, bench_case.q),
                                           bench_case.T_world_base, &result->errors));
  for (const JointError& e : result->errors.joints) {
    if (e.independent && e.error > (e.prismatic ? kFailedPrismatic : kFailedRevolute)) {
      result->failed = true;
    }
  }
  return Status::Ok();
}

ErrorStats SummarizeErrors(std::vector<double> values) {
  ErrorStats stats;
  if (values.empty()) return stats;
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (const double v : values) sum += v;
  stats.mean = sum / static_cast<double>(values.size());
  const size_t k = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
  stats.p95 = values[std::min(std::max<size_t>(k, 1) - 1, values.size() - 1)];
  stats.max = values.back();
  return stats;
}

}  // namespace edgefit
