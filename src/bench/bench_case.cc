#include "edgefit/bench/bench_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "edgefit/core/split_mix64.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/scanner/random_joints.h"
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

namespace {

// The first link with a mesh that none of 8 scanners around the model sees
// (3 mm spacing, no noise, accessories or clutter), or "" when every one is
// seen. With a bench's 3 scanners a link can also go unseen by occlusion
// alone; the fit must handle that, so this check uses more scanners.
Status BuriedLink(const KinematicModel& model, const BenchCase& c, std::string* buried) {
  AssetScanOptions options;
  options.clutter = 0;
  options.scanners = 8;
  options.scan.spacing = 0.003;
  options.scan.noise_sigma = 0.0;
  options.seed = c.seed;
  VirtualScan scan;
  EDGEFIT_RETURN_IF_ERROR(ScanAsset(model, c.q, c.T_world_base, options, &scan, nullptr));
  const LabelCounts counts = CountLabels(scan, model);
  buried->clear();
  for (size_t k = 0; k < counts.per_link.size(); ++k) {
    if (counts.per_link[k].second == 0 && !model.links()[k].mesh.empty()) {
      *buried = counts.per_link[k].first;
      break;
    }
  }
  return Status::Ok();
}

}  // namespace

Status RandomPostureCases(const KinematicModel& model, int count, uint64_t seed, double base_range,
                          std::vector<BenchCase>* cases,
                          const std::function<void(const std::string&)>& redrawn) {
  constexpr uint64_t kDraws = 16;
  for (int i = 0; i < count; ++i) {
    BenchCase c = MakeBenchCase("random_" + std::to_string(i), seed,
                                1000 + static_cast<uint64_t>(i), base_range);
    std::string buried;
    for (uint64_t draw = 0;; ++draw) {
      if (draw == kDraws) {
        return Status::Error(c.name + ": every one of " + std::to_string(kDraws) +
                             " random postures buries " + buried);
      }
      if (!RandomJointValuesAboveFloor(model, c.T_world_base, 0.0, Mix64(c.seed + draw), &c.q)) {
        return Status::Error(c.name + ": no random posture of the model stays above the floor");
      }
      EDGEFIT_RETURN_IF_ERROR(BuriedLink(model, c, &buried));
      if (buried.empty()) break;
      if (redrawn)
        redrawn(c.name + ": posture redrawn, " + buried + " is seen from none of 8 scanners");
    }
    cases->push_back(std::move(c));
  }
  return Status::Ok();
}

namespace {

// The shortest decimal that reads back as the same double.
std::string Exact(double value) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

}  // namespace

std::string ScanFlagsFor(const KinematicModel& model, const BenchCase& bench_case) {
  const Eigen::Vector3d t = bench_case.T_world_base.translation();
  const Eigen::Matrix3d R = bench_case.T_world_base.rotation();
  std::string flags = "--base=" + Exact(t.x()) + "," + Exact(t.y()) + "," +
                      Exact(std::atan2(R(1, 0), R(0, 0)) * 180.0 / M_PI) +
                      " --seed=" + std::to_string(bench_case.seed) + " --joints=";
  bool first = true;
  for (size_t j = 0; j < model.joints().size() && j < bench_case.q.size(); ++j) {
    if (!model.joints()[j].IsIndependent()) continue;
    flags += (first ? "" : ",") + model.joints()[j].name + "=" + Exact(bench_case.q[j]);
    first = false;
  }
  return flags;
}

Status ScanBenchCase(const KinematicModel& model, const BenchCase& bench_case,
                     AssetScanOptions scan_options, VirtualScan* scan, Pose* T_survey_world) {
  scan_options.seed = bench_case.seed;
  std::vector<Pose> T_world_scanners;
  EDGEFIT_RETURN_IF_ERROR(ScanAsset(model, bench_case.q, bench_case.T_world_base, scan_options,
                                    scan, &T_world_scanners));
  std::vector<Pose> T_survey_scanners;
  for (const OrganizedScan& s : scan->scans.scans) T_survey_scanners.push_back(s.T_world_scanner());
  *T_survey_world = SurveyFrame(T_world_scanners, T_survey_scanners);
  return Status::Ok();
}

Status FitBenchCase(const KinematicModel& model, const BenchCase& bench_case, const ScanSet& scans,
                    const Pose& T_survey_world, const FitOptions& fit_options, BenchResult* result,
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
  EDGEFIT_RETURN_IF_ERROR(
      CompareWithTruth(model, fit.q, fit.T_world_base, NamedJointValues(model, bench_case.q),
                       bench_case.T_world_base, T_survey_world, &result->errors,
                       fit.base_symmetry));
  MarkUnobservableJoints(fit.bodies, &result->errors);
  for (const JointError& e : result->errors.joints) {
    if (e.independent && !e.unobservable &&
        e.error > (e.prismatic ? kFailedPrismatic : kFailedRevolute)) {
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
