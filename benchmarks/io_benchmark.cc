// Scan I/O throughput on a ~5 M point scan generated in memory: PTX parse
// and read, E57 read and write against PTX write (same scan, same run).
//
//   cmake -S . -B build-scan -G Ninja -DCMAKE_BUILD_TYPE=Release -DEDGEFIT_BUILD_BENCHMARKS=ON
//   cmake --build build-scan --target io_benchmark && build-scan/benchmarks/io_benchmark
//
// Reports bytes_per_second (MB/s) for parsing alone (lattice estimation off)
// and for the full read (file read + parse + layout detection + lattice).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "edgefit/core/atomic_file.h"
#include "edgefit/io/e57.h"
#include "edgefit/io/ptx.h"
#include "edgefit/io/scan_io.h"

namespace edgefit {
namespace {

constexpr int kRows = 2000, kCols = 2500;  // 5 M cells

// A scanner in a 12 x 9 x 4 m room, 10% missing returns.
const ScanSet& RoomScan() {
  static const ScanSet set = [] {
    OrganizedScan scan(kRows, kCols);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int c = 0; c < kCols; ++c) {
      const double a = 2.0 * M_PI * c / kCols;
      for (int r = 0; r < kRows; ++r) {
        const double e = -1.0 + 2.2 * r / kRows;
        const Eigen::Vector3d d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
        const double t = std::min({6.0 / std::max(1e-9, std::abs(d.x())), 4.5 / std::max(1e-9, std::abs(d.y())),
                                   (d.z() > 0 ? 2.5 : 1.5) / std::max(1e-9, std::abs(d.z()))});
        if (uniform(rng) < 0.1) continue;
        scan.SetPoint(scan.Index(r, c), (t * d).cast<float>(), static_cast<float>(uniform(rng)));
      }
    }
    ScanSet set;
    set.scans.push_back(std::move(scan));
    return set;
  }();
  return set;
}

std::string BenchPath(const char* extension) {
  return "/tmp/edgefit_io_benchmark_" + std::to_string(::getpid()) + extension;
}

// RoomScan written once as `extension` (.ptx or .e57).
const std::string& WrittenOnce(const char* extension) {
  static std::string paths[2];
  std::string& path = paths[std::string(extension) == ".e57" ? 1 : 0];
  if (path.empty()) {
    path = BenchPath(extension);
    const Status status = WriteScans(path, RoomScan(), WriteOptions());
    if (!status.ok()) std::fprintf(stderr, "%s\n", status.message().c_str());
  }
  return path;
}

const std::string& PtxPath() { return WrittenOnce(".ptx"); }

void BM_ParsePtx(benchmark::State& state) {
  std::string content;
  if (!ReadFileToString(PtxPath(), &content).ok()) {
    state.SkipWithError("cannot read the generated PTX");
    return;
  }
  ReadOptions options;
  options.estimate_lattice = false;
  for (auto _ : state) {
    ScanSet set;
    const Status status = ParsePtx(content, "bench.ptx", options, &set);
    if (!status.ok()) state.SkipWithError(status.message().c_str());
    benchmark::DoNotOptimize(set);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(content.size()));
  state.counters["points"] = static_cast<double>(kRows) * kCols;
}
BENCHMARK(BM_ParsePtx)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ReadScansPtxWithLattice(benchmark::State& state) {
  std::string content;
  (void)ReadFileToString(PtxPath(), &content);
  for (auto _ : state) {
    ScanSet set;
    const Status status = ReadScans(PtxPath(), ReadOptions(), &set);
    if (!status.ok()) state.SkipWithError(status.message().c_str());
    benchmark::DoNotOptimize(set);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(content.size()));
}
BENCHMARK(BM_ReadScansPtxWithLattice)->Unit(benchmark::kMillisecond)->UseRealTime();

// Streams the E57 file from disk into an OrganizedScan (pages, checksums,
// bitpack decoding), lattice off: compare with BM_ParsePtx.
void BM_ReadE57(benchmark::State& state) {
  const std::string& path = WrittenOnce(".e57");
  ReadOptions options;
  options.estimate_lattice = false;
  for (auto _ : state) {
    ScanSet set;
    const Status status = ReadE57(path, options, &set);
    if (!status.ok()) state.SkipWithError(status.message().c_str());
    benchmark::DoNotOptimize(set);
  }
  state.counters["points"] = static_cast<double>(kRows) * kCols;
}
BENCHMARK(BM_ReadE57)->Unit(benchmark::kMillisecond)->UseRealTime();

// Writing the same scan, E57 against PTX.
void BM_Write(benchmark::State& state, const char* extension) {
  const std::string path = BenchPath(extension) + ".out";
  for (auto _ : state) {
    const Status status = std::string(extension) == ".e57" ? WriteE57(path, RoomScan()) : WritePtx(path, RoomScan());
    if (!status.ok()) state.SkipWithError(status.message().c_str());
  }
  std::remove(path.c_str());
}
BENCHMARK_CAPTURE(BM_Write, e57, ".e57")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Write, ptx, ".ptx")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace edgefit

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::remove(edgefit::BenchPath(".ptx").c_str());
  std::remove(edgefit::BenchPath(".e57").c_str());
  return 0;
}
