// Two-stage weighted-PCA normals on the scan lattice (paper Sec. 4.1).
//
// For each valid cell i the neighbours are the valid cells of its adaptive
// pixel window, half size ceil(radius / (range_i * step)) per direction
// (capped at max_half_window), that lie within `radius` of p_i in 3D; no
// 3D kd-tree is needed.
//   Stage 1: WPCA with the Gaussian weights of Eq. (1),
//            w_k = exp(-|p_k - p_i|^2 / (2 h_i^2)), h_i = half the largest
//            neighbour distance, gives the initial normal n_i^(0).
//   Stage 2: WPCA (same weights) over the neighbours whose initial normals
//            agree, |n_k^(0) . n_i^(0)| > tau_align (Eq. 2), gives n_i; it
//            does not smooth across sharp edges.
// Normals are unit, in the scanner frame, oriented toward the scanner
// (n . p < 0). A cell with fewer than 3 neighbours (itself included) gets a
// NaN normal; when stage 2 keeps fewer than 3, n_i = n_i^(0).
// OpenMP over columns; each cell's result depends only on its inputs, so the
// output is identical for any thread count.
#ifndef EDGEFIT_EDGES_GRID_NORMALS_H_
#define EDGEFIT_EDGES_GRID_NORMALS_H_

#include <vector>

#include "edgefit/edges/grid_cloud.h"

namespace edgefit {

struct GridNormalOptions {
  double radius = 0.005;     // [m] physical neighbourhood radius
  int max_half_window = 8;   // [pixels] cap of the half window
  double tau_align = 0.866;  // Eq. (2), cos 30 deg
};

// Unit normals as structure of arrays, cell order; NaN when undefined.
struct GridNormals {
  std::vector<float> x, y, z;
  size_t size() const { return x.size(); }
  bool IsValid(size_t i) const { return !std::isnan(x[i]); }
  void Resize(size_t n);
};

// Stage 1 only: the initial normals n^(0) (exposed for tests and benchmarks).
void EstimateInitialNormals(const GridCloud& cloud, const GridNormalOptions& options,
                            GridNormals* initial);
// Stage 2 from given initial normals.
void RefineNormals(const GridCloud& cloud, const GridNormalOptions& options,
                   const GridNormals& initial, GridNormals* normals);
// Both stages: the final normals n_i of Sec. 4.1.
void EstimateGridNormals(const GridCloud& cloud, const GridNormalOptions& options,
                         GridNormals* normals);

}  // namespace edgefit

#endif  // EDGEFIT_EDGES_GRID_NORMALS_H_
