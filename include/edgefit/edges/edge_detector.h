// Fast edge detection on the scan lattice and edge weights (paper Sec. 4):
//   4.1 two-stage weighted-PCA normals on each scan's grid (Eq. 1-2),
//   4.2 annular normal-consistency edge score (Eq. 3-4), S_i < tau_dot -> candidate,
//   4.3 region growing over the candidates of all scans together (Eq. 5),
//       regions under tau_min points dropped, w_edge = w_high in valid regions,
//       1 elsewhere (Eq. 6).
// Lengths in metres inside; the paper's millimetre parameters are converted.
#ifndef EDGEFIT_EDGES_EDGE_DETECTOR_H_
#define EDGEFIT_EDGES_EDGE_DETECTOR_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct EdgeDetectionOptions {
  // 4.1 Normals. Physical radius of the adaptive pixel window [m]: the half
  // window in pixels is ceil(normal_radius / (range * angular step)), so it
  // covers the same surface patch near and far.
  double normal_radius = 0.005;
  int max_half_window = 8;           // [pixels] cap for very near points
  double tau_align = 0.866;          // Eq. (2): |n_k . n_ij| > cos 30 deg
  // 4.2 Edge score over the annulus r_min < d < r_max (Eq. 3).
  double r_min = 0.005;              // [m] (paper: 5 mm)
  double r_max = 0.010;              // [m] (paper: 10 mm)
  // S_i < tau_dot -> candidate. 0.8 chosen by measurement (BENCHMARK.md, "Edge
  // detection"): the lowest share of accessory points with w_high at which the
  // robot's true edges are still found; higher values find more edges but give
  // harness tubes w_high more often than the links.
  double tau_dot = 0.8;
  // 4.3 Region growing.
  double region_radius = 0.004;      // [m] neighbour radius when growing
  double tau_region = 0.95;          // Eq. (5)
  int tau_min = 300;                 // [points] smaller regions are noise
  // Eq. (6).
  double w_high = 10.0;

  bool IsValid(std::string* error) const;
};

struct EdgeTimings {
  double normals = 0.0;         // [s] 4.1
  double scores = 0.0;          // [s] 4.2
  double region_growing = 0.0;  // [s] 4.3 incl. the kd-tree
  double total = 0.0;
};

struct EdgeDetectionResult {
  // Per scan, per cell in cell order (OrganizedScan::Index): w_edge of a
  // valid point (1 or w_high), 0 for a missing cell.
  std::vector<std::vector<float>> w_edge;
  // Per scan, per cell: final normal (4.1, scanner frame, unit; NaN when the
  // cell is missing or has too few neighbours) and edge score S_i (4.2; NaN
  // when undefined).
  std::vector<std::vector<Eigen::Vector3f>> normals;
  std::vector<std::vector<float>> scores;
  size_t points = 0;       // valid points
  size_t candidates = 0;   // S_i < tau_dot
  size_t edge_points = 0;  // in valid regions (w_high)
  size_t regions = 0;      // valid regions
  EdgeTimings timings;
};

// Runs 4.1-4.3 on every organized scan of `scans` (their lattices must be
// set). Fails on invalid options, unorganized scans or scans without lattice.
// Deterministic for any thread count.
Status DetectEdges(const ScanSet& scans, const EdgeDetectionOptions& options,
                   EdgeDetectionResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_EDGES_EDGE_DETECTOR_H_
