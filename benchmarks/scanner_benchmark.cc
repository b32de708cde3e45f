// Virtual scanner throughput (paper Sec. 7.3 datasets hold ~5 M points):
// rays per second for a ~5 M ray scan of the real KUKA KR150 R3100 on a
// floor (a procedural box-and-cylinder "robot" when /work/shared is absent),
// with 1 and 2 OpenMP threads. The BVH is built once, outside the timing.
//   build-scanner/benchmarks/scanner_benchmark --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <glog/logging.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/model_scene.h"

namespace edgefit {
namespace {

#ifndef EDGEFIT_SHARED_DIR
#define EDGEFIT_SHARED_DIR "/work/shared"
#endif

struct Fixture {
  Scene scene;
  std::vector<Pose> poses;
  VirtualScanOptions options;
  std::unique_ptr<VirtualScanner> scanner;
  std::string what;
};

SceneMesh Floor() {
  SceneMesh m;
  m.mesh_world.vertices = {{-30, -30, 0}, {30, -30, 0}, {30, 30, 0}, {-30, 30, 0}};
  m.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.kind = "floor";
  return m;
}

Fixture& GetFixture() {
  static Fixture* fixture = [] {
    auto* f = new Fixture;
    f->scene.meshes.push_back(Floor());
    const std::string urdf =
        std::string(EDGEFIT_SHARED_DIR) + "/robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf";
    KinematicModel model;
    Eigen::AlignedBox3d box;
    if (std::filesystem::exists(urdf) && LoadKinematicModel(urdf, {}, &model).ok()) {
      const std::vector<double> q = RandomJointValues(model, 1);
      AddModelToScene(model, model.ForwardKinematics(q), &f->scene);
      box = model.BoundingBox(q);
      f->what = "kuka_kr150r3100_2";
    } else {
      // Procedural stand-in: a base box, a column cylinder and an arm box.
      const struct { Eigen::Vector3d size, centre; } parts[] = {
          {{1.0, 1.0, 0.5}, {0, 0, 0.25}}, {{0.3, 0.3, 1.5}, {0, 0, 1.25}},
          {{1.6, 0.3, 0.3}, {0.6, 0, 2.1}}};
      for (int k = 0; k < 3; ++k) {
        SceneMesh m;
        m.mesh_world.Append(MakeBoxMesh(parts[k].size), Pose(Eigen::Translation3d(parts[k].centre)));
        m.label = LinkLabel(k);
        m.link = k;
        m.kind = "link";
        box.extend(m.mesh_world.BoundingBox());
        f->scene.meshes.push_back(std::move(m));
      }
      f->what = "procedural";
    }
    ScannerPlacementOptions placement;
    placement.count = 3;
    placement.seed = 1;
    f->poses = PlaceScanners(box, placement);
    // Spacing chosen so the 3 scans hold ~5 M cells in total.
    f->options.spacing = 0.0017;
    VirtualScan probe;
    CHECK(VirtualScanner::Create(f->scene, f->options, &f->scanner).ok());
    for (int i = 0; i < 8; ++i) {
      CHECK(f->scanner->Scan(f->poses, f->options, &probe).ok());
      const double scale = std::sqrt(static_cast<double>(probe.rays) / 5.0e6);
      if (std::abs(scale - 1.0) < 0.02) break;
      f->options.spacing *= scale;
    }
    return f;
  }();
  return *fixture;
}

void BM_ScanScene(benchmark::State& state) {
  Fixture& f = GetFixture();
  const int saved = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  VirtualScan scan;
  double ray_seconds = 0.0;
  for (auto _ : state) {
    CHECK(f.scanner->Scan(f.poses, f.options, &scan).ok());
    for (double s : scan.ray_seconds) ray_seconds += s;
  }
  omp_set_num_threads(saved);
  state.SetLabel(f.what + ", " + std::to_string(f.scanner->triangle_count()) + " triangles");
  state.counters["rays"] = static_cast<double>(scan.rays);
  state.counters["valid"] = static_cast<double>(scan.scans.TotalValid());
  state.counters["spacing_mm"] = f.options.spacing * 1e3;
  state.counters["rays_per_s"] = benchmark::Counter(
      static_cast<double>(scan.rays) * static_cast<double>(state.iterations()) / ray_seconds);
  state.SetItemsProcessed(static_cast<int64_t>(scan.rays) * state.iterations());
}
BENCHMARK(BM_ScanScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole call as the command line makes it: BVH build + edge indices + scan.
void BM_ScanSceneWithBuild(benchmark::State& state) {
  Fixture& f = GetFixture();
  VirtualScan scan;
  for (auto _ : state) CHECK(ScanScene(f.scene, f.poses, f.options, &scan).ok());
  state.counters["rays"] = static_cast<double>(scan.rays);
}
BENCHMARK(BM_ScanSceneWithBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace edgefit

BENCHMARK_MAIN();
