// Annular normal-consistency edge score on the scan lattice (paper Sec. 4.2).
//
// For each cell i with a normal, N_i holds the cells of its pixel window
// covering r_max (half size ceil(r_max / (range_i * step)), capped) whose
// points satisfy r_min < |p_k - p_i| < r_max (Eq. 3) and that have a normal;
//   S_i = (1 / |N_i|) sum_{k in N_i} |n_i . n_k|          (Eq. 4)
// is ~1 on planes and drops near sharp edges. S_i < tau_dot marks a
// candidate (edge_detector.h). S_i is NaN when n_i is undefined or N_i empty.
#ifndef EDGEFIT_EDGES_EDGE_SCORE_H_
#define EDGEFIT_EDGES_EDGE_SCORE_H_

#include <vector>

#include "edgefit/edges/grid_cloud.h"
#include "edgefit/edges/grid_normals.h"

namespace edgefit {

struct EdgeScoreOptions {
  double r_min = 0.005;  // [m] Eq. (3)
  double r_max = 0.010;  // [m] Eq. (3)
  // [pixels] cap of the half window; near points whose window would be
  // larger see only part of the annulus.
  int max_half_window = 16;
};

// Scores S_i (Eq. 4) in cell order. OpenMP over columns; identical output
// for any thread count.
void ComputeEdgeScores(const GridCloud& cloud, const GridNormals& normals,
                       const EdgeScoreOptions& options, std::vector<float>* scores);

}  // namespace edgefit

#endif  // EDGEFIT_EDGES_EDGE_SCORE_H_
