// Correspondence search speed (paper Sec. 5.2.1: the lattice search "instead
// of a 3D search") on a ~5 M point virtual scan of the bundled robot
// (assets/robot/robot.urdf, posture "home") on a floor from 3 scanners, 1 mm
// noise: 1 M source points (CAD samples of the posed robot, each moved by a
// deterministic offset of up to +/- 2 mm per axis) matched by
//   - the lattice search (window 2 and 3), 1 and 2 threads;
//   - the cropped kd-tree: build (crop = robot box + 5 cm) and search apart.
//   build-corr/benchmarks/correspondence_benchmark --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <glog/logging.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "bundled_robot_scan.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/correspondence/kdtree_search.h"
#include "edgefit/correspondence/lattice_search.h"
#include "edgefit/model/surface_sampler.h"

namespace edgefit {
namespace {

#ifndef EDGEFIT_SOURCE_DIR
#define EDGEFIT_SOURCE_DIR "."
#endif

constexpr size_t kSources = 1'000'000;

struct Fixture {
  ScanSet scans;
  std::vector<Eigen::Vector3f> q_world;
  Eigen::AlignedBox3d crop_world;
};

// [-1, 1) from Mix64: a fixed offset per source, independent of threads.
float Jitter(uint64_t x) {
  return static_cast<float>(static_cast<double>(Mix64(x + 0x9e3779b97f4a7c15ULL) >> 11) *
                                0x1.0p-53 * 2.0 -
                            1.0);
}

Fixture& GetFixture() {
  static Fixture* fixture = [] {
    auto* f = new Fixture;
    BundledRobotScan robot = ScanBundledRobot();
    const KinematicModel& model = robot.model;
    const std::vector<Pose> T_world_link = model.ForwardKinematics(robot.q);
    const Eigen::AlignedBox3d box = model.BoundingBox(robot.q);
    f->scans = std::move(robot.scans);
    LOG(INFO) << "scan: " << f->scans.TotalValid() << " valid points, spacing "
              << robot.spacing * 1e3 << " mm";

    SamplingOptions sampling;
    sampling.spacing = 0.002;
    const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
    std::vector<Eigen::Vector3f> all;
    for (size_t l = 0; l < samples.size(); ++l) {
      for (const Eigen::Vector3f& p : samples[l].points) {
        all.push_back((T_world_link[l] * p.cast<double>()).cast<float>());
      }
    }
    CHECK(!all.empty());
    f->q_world.reserve(kSources);
    for (size_t i = 0; i < kSources; ++i) {
      const size_t j = static_cast<size_t>(static_cast<double>(i) * all.size() / kSources);
      const Eigen::Vector3f offset(Jitter(3 * i), Jitter(3 * i + 1), Jitter(3 * i + 2));
      f->q_world.push_back(all[j] + 0.002f * offset);
    }
    f->crop_world = box;
    f->crop_world.extend(box.min() - Eigen::Vector3d::Constant(0.05));
    f->crop_world.extend(box.max() + Eigen::Vector3d::Constant(0.05));
    return f;
  }();
  return *fixture;
}

void SetCounters(benchmark::State& state, size_t matched) {
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSources));
  state.counters["matched"] = static_cast<double>(matched) / kSources;
}

// Args: window, threads.
void BM_LatticeSearch(benchmark::State& state) {
  Fixture& f = GetFixture();
  omp_set_num_threads(static_cast<int>(state.range(1)));
  LatticeSearch search(&f.scans, nullptr);
  CorrespondenceOptions options;
  options.window = static_cast<int>(state.range(0));
  std::vector<Correspondence> out;
  for (auto _ : state) {
    search.Find(f.q_world, options, &out);
    benchmark::DoNotOptimize(out.data());
  }
  SetCounters(state, out.size());
}
BENCHMARK(BM_LatticeSearch)
    ->ArgNames({"window", "threads"})
    ->Args({2, 1})
    ->Args({2, 2})
    ->Args({3, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Collects the cropped points and builds the tree (single-threaded nanoflann).
void BM_KdTreeBuild(benchmark::State& state) {
  Fixture& f = GetFixture();
  size_t points = 0;
  for (auto _ : state) {
    KdTreeSearch search(&f.scans, nullptr);
    search.SetCrop(f.crop_world);
    points = search.size();
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_KdTreeBuild)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// Args: threads. The tree is built once, outside the timing.
void BM_KdTreeSearch(benchmark::State& state) {
  Fixture& f = GetFixture();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  KdTreeSearch search(&f.scans, nullptr);
  search.SetCrop(f.crop_world);
  CorrespondenceOptions options;
  std::vector<Correspondence> out;
  for (auto _ : state) {
    search.Find(f.q_world, f.crop_world, options, &out);
    benchmark::DoNotOptimize(out.data());
  }
  SetCounters(state, out.size());
}
BENCHMARK(BM_KdTreeSearch)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace edgefit

BENCHMARK_MAIN();
