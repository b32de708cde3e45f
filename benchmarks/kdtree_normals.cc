// A whole-process reference for the fit's speed (BENCHMARK.md, "Speed of a
// fit"): reads a scan file as `edgefit fit` does (its lattice aside) and
// computes every valid point's normal with a kd-tree (kdtree_normals.h).
// Timed as a whole process beside the fit (farm-bench --vs), it makes a
// ratio that holds on any machine.
//
//   kdtree_normals --scan=robot.ptx [--radius_mm=5] [--threads=N] [--out_ply=points.ply]
//
// --out_ply writes the valid points in world coordinates for other
// libraries' normal passes (benchmarks/open3d_normals.py).
#include <gflags/gflags.h>
#include <omp.h>

#include <chrono>
#include <cstdio>

#include "edgefit/io/scan_io.h"
#include "kdtree_normals.h"

DEFINE_string(scan, "", "scan file (.ptx, .e57, .pcd, .ply)");
DEFINE_double(radius_mm, 5.0, "neighbourhood radius [mm]");
DEFINE_int32(threads, 0, "threads (0: OpenMP's default)");
DEFINE_string(out_ply, "", "write the valid points (world) to this PLY and stop");

int main(int argc, char** argv) {
  gflags::SetUsageMessage("kdtree_normals --scan=FILE [--radius_mm=5] [--threads=N]");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  if (FLAGS_scan.empty() || !(FLAGS_radius_mm > 0.0)) {
    std::fprintf(stderr, "kdtree_normals: --scan is required and --radius_mm must be positive\n");
    return 2;
  }
  if (FLAGS_threads > 0) omp_set_num_threads(FLAGS_threads);
  const auto start = std::chrono::steady_clock::now();
  edgefit::ReadOptions read;
  read.estimate_lattice = false;
  read.intensity = !FLAGS_out_ply.empty();  // the normal pass, as the fit, reads none
  edgefit::ScanSet scans;
  const edgefit::Status status = edgefit::ReadScans(FLAGS_scan, read, &scans);
  if (!status.ok()) {
    std::fprintf(stderr, "kdtree_normals: %s\n", status.message().c_str());
    return 2;
  }
  if (!FLAGS_out_ply.empty()) {
    const edgefit::Status written =
        edgefit::WriteScans(FLAGS_out_ply, scans, edgefit::WriteOptions());
    if (!written.ok()) std::fprintf(stderr, "kdtree_normals: %s\n", written.message().c_str());
    return written.ok() ? 0 : 2;
  }
  const auto loaded = std::chrono::steady_clock::now();
  size_t points = 0, with_normal = 0;
  for (const edgefit::OrganizedScan& scan : scans.scans) {
    const std::vector<Eigen::Vector3f> cloud = edgefit::bench::ValidPoints(scan);
    const std::vector<Eigen::Vector3f> normals =
        edgefit::bench::KdTreeNormals(cloud, static_cast<float>(1e-3 * FLAGS_radius_mm));
    points += cloud.size();
    for (const Eigen::Vector3f& n : normals) with_normal += n.squaredNorm() > 0.0f;
  }
  const auto done = std::chrono::steady_clock::now();
  std::printf("%zu points, %zu with a normal; read %.2f s, normals %.2f s\n", points, with_normal,
              std::chrono::duration<double>(loaded - start).count(),
              std::chrono::duration<double>(done - loaded).count());
  return 0;
}
