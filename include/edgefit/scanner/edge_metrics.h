// Edge weights scored against the virtual scanner's ground truth (paper
// Sec. 4 hypothesis): structural edges of the modelled links should get
// w_high (recall), points that get w_high should be true edges (precision),
// and non-modelled accessories should rarely get w_high (accessory share).
#ifndef EDGEFIT_SCANNER_EDGE_METRICS_H_
#define EDGEFIT_SCANNER_EDGE_METRICS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace edgefit {

struct EdgeMetrics {
  size_t link_points = 0;        // points on modelled links
  size_t true_edges = 0;         // link points flagged as true edges (kTrueEdgeFlag)
  size_t link_high = 0;          // link points with w_edge > 1
  size_t true_positives = 0;     // true edges with w_edge > 1
  size_t accessory_points = 0;
  size_t accessory_high = 0;     // accessory points with w_edge > 1
  size_t background_points = 0;
  size_t background_high = 0;

  // Over link points: TP / link_high and TP / true_edges (0 when undefined).
  double precision() const;
  double recall() const;
  // Share of accessory points that get w_high: the paper's hypothesis is
  // that it stays small.
  double accessory_share() const;
  // Share of all w_high points of the asset (links + accessories) that lie
  // on accessories.
  double accessory_share_of_high() const;
  std::string BriefReport() const;
};

// `labels` and `w_edge` hold one entry per cell of each scan in the same
// order (e.g. both in file point order: the --labels sidecar and the
// edgefit edges weights file). A point counts as an edge when w_edge > 1.
EdgeMetrics EvaluateEdgeWeights(const std::vector<std::vector<uint16_t>>& labels,
                                const std::vector<std::vector<float>>& w_edge);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_EDGE_METRICS_H_
