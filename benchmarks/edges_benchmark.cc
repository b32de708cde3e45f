// Edge detection speed (paper Sec. 4, 7.2: ~5 M points per dataset) on a
// ~5 M point virtual scan of the bundled robot (assets/robot/robot.urdf,
// posture "home") on a floor from 3 scanners at ~1.7 mm spacing, 1 mm noise:
// per-stage kernels (4.1 normals, 4.2 scores, 4.3 region growing), the whole
// DetectEdges, the whole fit at its defaults (Fit(): every stage to the
// verdict, reading aside), and as reference for both a nanoflann kd-tree
// normal estimation at the same physical radius (tree build + radius search
// + PCA), 1 and 2 threads.
//   build-edges/benchmarks/edges_benchmark --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <glog/logging.h>
#include <omp.h>

#include <cmath>

#include "bundled_robot_scan.h"
#include "kdtree_normals.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/edges/edge_score.h"
#include "edgefit/edges/grid_normals.h"
#include "edgefit/edges/region_growing.h"
#include "edgefit/pipeline/fit.h"

namespace edgefit {
namespace {

#ifndef EDGEFIT_SOURCE_DIR
#define EDGEFIT_SOURCE_DIR "."
#endif

struct Fixture {
  KinematicModel model;
  ScanSet scans;
  std::vector<GridCloud> clouds;
  std::vector<GridNormals> normals;
  std::vector<std::vector<float>> scores;
  EdgeCandidates candidates;
  EdgeDetectionOptions options;
  double spacing = 0.0017;
};

Fixture& GetFixture() {
  static Fixture* fixture = [] {
    auto* f = new Fixture;
    BundledRobotScan robot = ScanBundledRobot();
    f->spacing = robot.spacing;
    f->model = std::move(robot.model);
    f->scans = std::move(robot.scans);
    GridNormalOptions normal_options;
    EdgeScoreOptions score_options;
    score_options.max_half_window = 16;
    for (const OrganizedScan& s : f->scans.scans) {
      f->clouds.push_back(GridCloud::FromScan(s));
      f->normals.emplace_back();
      EstimateGridNormals(f->clouds.back(), normal_options, &f->normals.back());
      f->scores.emplace_back();
      ComputeEdgeScores(f->clouds.back(), f->normals.back(), score_options, &f->scores.back());
      const Eigen::Matrix3f R = s.T_world_scanner().linear().cast<float>();
      const Eigen::Vector3f t = s.T_world_scanner().translation().cast<float>();
      const GridNormals& n = f->normals.back();
      for (size_t i = 0; i < s.size(); ++i) {
        if (f->scores.back()[i] < f->options.tau_dot) {
          f->candidates.Add(R * s.point_scanner(i) + t,
                            R * Eigen::Vector3f(n.x[i], n.y[i], n.z[i]), f->scores.back()[i]);
        }
      }
    }
    return f;
  }();
  return *fixture;
}

class ThreadScope {
 public:
  explicit ThreadScope(int threads) : saved_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~ThreadScope() { omp_set_num_threads(saved_); }

 private:
  int saved_;
};

void SetPointCounters(benchmark::State& state, const Fixture& f) {
  state.counters["points"] = static_cast<double>(f.scans.TotalValid());
  state.counters["cells"] = static_cast<double>(f.scans.TotalCells());
  state.counters["spacing_mm"] = f.spacing * 1e3;
}

void BM_GridNormals(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  GridNormals normals;
  for (auto _ : state) {
    for (const GridCloud& cloud : f.clouds) EstimateGridNormals(cloud, GridNormalOptions(), &normals);
  }
  SetPointCounters(state, f);
}
BENCHMARK(BM_GridNormals)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_EdgeScores(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  std::vector<float> scores;
  for (auto _ : state) {
    for (size_t s = 0; s < f.clouds.size(); ++s) {
      ComputeEdgeScores(f.clouds[s], f.normals[s], EdgeScoreOptions(), &scores);
    }
  }
  SetPointCounters(state, f);
}
BENCHMARK(BM_EdgeScores)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RegionGrowing(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  RegionGrowingOptions options;
  RegionGrowingResult result;
  for (auto _ : state) GrowEdgeRegions(f.candidates, options, &result);
  state.counters["candidates"] = static_cast<double>(f.candidates.size());
  state.counters["regions"] = static_cast<double>(result.regions);
}
BENCHMARK(BM_RegionGrowing)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DetectEdges(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  EdgeDetectionResult result;
  for (auto _ : state) CHECK(DetectEdges(f.scans, f.options, &result).ok());
  SetPointCounters(state, f);
  state.counters["normals_s"] = result.timings.normals;
  state.counters["scores_s"] = result.timings.scores;
  state.counters["regions_s"] = result.timings.region_growing;
  state.counters["candidates"] = static_cast<double>(result.candidates);
  state.counters["edge_points"] = static_cast<double>(result.edge_points);
  // Memory: the result (normal 12 + score 4 + w_edge 4 bytes per cell), the
  // per-scan working arrays of the largest scan (GridCloud 16 + initial and
  // final normals 24 bytes per cell) and the candidates (p, n, score, cell:
  // 36 bytes) with their kd-tree index and ~neighbour lists (measured
  // separately as 4 bytes per neighbour, <= 64 neighbours assumed).
  size_t largest = 0;
  for (const OrganizedScan& s : f.scans.scans) largest = std::max(largest, s.size());
  const double bytes = 20.0 * static_cast<double>(f.scans.TotalCells()) + 40.0 * largest +
                       static_cast<double>(result.candidates) * (36.0 + 8.0 + 4.0 * 64.0);
  state.counters["bytes_per_point"] = bytes / static_cast<double>(f.scans.TotalValid());
}
BENCHMARK(BM_DetectEdges)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole fit of the bundled robot (no gun) at the defaults, edges (none
// with the default uniform weights) to the verdict; the scan is in memory.
void BM_WholeFit(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  FitResult result;
  for (auto _ : state) {
    CHECK(Fit(f.model, f.scans, FitOptions(), nullptr, &result).ok());
    CHECK(result.ok) << result.message;
  }
  SetPointCounters(state, f);
  state.counters["base_rough_s"] = result.timings.base_rough;
  state.counters["chain_s"] = result.timings.base_precise + result.timings.chain;
  state.counters["stations_s"] = result.timings.stations;
  state.counters["refine_s"] = result.timings.refine;
}
BENCHMARK(BM_WholeFit)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// Reference: the same radius with a 3D kd-tree instead of the lattice window
// (nanoflann tree per scan, radius search, one unweighted PCA per point).
void BM_KdTreeNormalsReference(benchmark::State& state) {
  Fixture& f = GetFixture();
  ThreadScope threads(static_cast<int>(state.range(0)));
  const float radius = static_cast<float>(f.options.normal_radius);
  std::vector<std::vector<Eigen::Vector3f>> points;
  for (const OrganizedScan& scan : f.scans.scans) points.push_back(bench::ValidPoints(scan));
  for (auto _ : state) {
    for (const auto& cloud : points) benchmark::DoNotOptimize(bench::KdTreeNormals(cloud, radius));
  }
  SetPointCounters(state, f);
}
BENCHMARK(BM_KdTreeNormalsReference)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace edgefit

BENCHMARK_MAIN();
