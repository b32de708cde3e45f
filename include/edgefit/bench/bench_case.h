// One scene of the paper's evaluation (Sec. 7.3-7.4) and its fit: a model
// in a posture on a base pose, scanned by the virtual scanner (with or
// without accessories), fitted, and scored against the scanner's truth.
// `edgefit bench` and benchmarks/robot_accuracy run these.
#ifndef EDGEFIT_BENCH_BENCH_CASE_H_
#define EDGEFIT_BENCH_BENCH_CASE_H_

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "edgefit/bench/fit_errors.h"
#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/fit.h"
#include "edgefit/scanner/asset_scan.h"

namespace edgefit {

struct BenchCase {
  std::string name;       // the posture's ("load", "random_3")
  std::vector<double> q;  // every joint, model order
  Pose T_world_base = Pose::Identity();
  uint64_t seed = 0;  // the scene's (AssetScanOptions::seed)
};

// Case i draws its base pose and scene seed from stream `stream` of `seed`:
// x, y uniform in [-base_range, base_range] [m], yaw uniform.
BenchCase MakeBenchCase(const std::string& name, uint64_t seed, uint64_t stream, double base_range);

// Every named posture of a postures file (assets/*/postures.json), posture
// i on stream i. Fails on a file that does not load or a posture that does
// not fit the model.
Status NamedPostureCases(const KinematicModel& model, const std::string& postures_file,
                         uint64_t seed, double base_range, std::vector<BenchCase>* cases);

// `count` seeded random postures ("random_0", ...) above the floor
// (RandomJointValuesAboveFloor), case i on stream 1000 + i, so adding named
// postures or more random ones does not change the others. Random postures
// are not checked for self-collision: a posture that buries a link with a
// mesh so that none of 8 scanners around the robot sees it (a forearm
// folded into the upper arm) is redrawn, at most 16 times. `redrawn` (may
// be null) is told each redraw: the case and the buried link.
Status RandomPostureCases(const KinematicModel& model, int count, uint64_t seed, double base_range,
                          std::vector<BenchCase>* cases,
                          const std::function<void(const std::string&)>& redrawn = nullptr);

// The `edgefit scan` flags that make the case's scene again: --base, --seed
// and --joints (radians, every independent joint), for rerunning one case
// of a bench by hand.
std::string ScanFlagsFor(const KinematicModel& model, const BenchCase& bench_case);

// A failed fit (the bound at which a benchmark counts a fit as failed): a
// revolute joint off by more than this [rad], a prismatic one by more than
// this [m].
constexpr double kFailedRevolute = 0.5 * M_PI / 180.0;
constexpr double kFailedPrismatic = 0.005;

struct BenchResult {
  size_t points = 0;  // valid scan points
  FitErrors errors;
  FitTimings timings;
  std::vector<BodyQuality> bodies;
  ChainRefinementSummary chain;  // refinement and covariance (joint_std)
  bool ok = false;               // the fit's own verdict (FitResult::ok)
  std::string message;
  bool failed = false;  // an observable independent joint beyond the bounds above
};

// The case's scene (ScanAsset with scan_options, its seed replaced by the
// case's): scan it once, fit it with several options. T_survey_world: the
// frame its stations' written poses put the world in (SurveyFrame).
Status ScanBenchCase(const KinematicModel& model, const BenchCase& bench_case,
                     AssetScanOptions scan_options, VirtualScan* scan, Pose* T_survey_world);

// Fits the scan of the case with fit_options and scores it; T_survey_world
// from ScanBenchCase.
Status FitBenchCase(const KinematicModel& model, const BenchCase& bench_case, const ScanSet& scans,
                    const Pose& T_survey_world, const FitOptions& fit_options, BenchResult* result,
                    const ProgressFn& progress = nullptr);

// Mean, 95th percentile (the smallest value at or above 95 % of them) and
// largest of a set of errors; all 0 for none.
struct ErrorStats {
  double mean = 0.0, p95 = 0.0, max = 0.0;
};
ErrorStats SummarizeErrors(std::vector<double> values);

}  // namespace edgefit

#endif  // EDGEFIT_BENCH_BENCH_CASE_H_
