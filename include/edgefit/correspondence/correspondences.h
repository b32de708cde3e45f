// Point-to-scan correspondences: for each source point (CAD samples of a
// posed link, world frame) the nearest valid scan point, gated by distance,
// carrying the target cell's edge weight w_edge (paper Sec. 5.2, Eq. (9)).
//
// Two searches share this output type (correspondence_search.h):
//   lattice (paper Sec. 5.2.1, "we leverage the 2D lattice of the TLS data
//     instead of a 3D search"): each query is projected onto every scan's
//     angular lattice and only a (2 window + 1)^2 block of cells around it is
//     searched, O(1) per query and scan with no index to build;
//   kd-tree: exact nearest neighbour among the valid points of all scans
//     inside a crop box (reference, and fallback for unorganized clouds).
#ifndef EDGEFIT_CORRESPONDENCE_CORRESPONDENCES_H_
#define EDGEFIT_CORRESPONDENCE_CORRESPONDENCES_H_

#include <cstdint>
#include <string>
#include <vector>

namespace edgefit {

// One matched source point.
struct Correspondence {
  int source = -1;       // index into the query points
  int scan = -1;         // index into ScanSet::scans
  int cell = -1;         // cell index in that scan (col * rows + row)
  float distance = 0.f;  // Euclidean distance source -> scan point [m]
  float weight = 1.f;    // w_edge of the target cell (1 without weights)
};

struct CorrespondenceOptions {
  // Matches farther than this are rejected [m]. 5 cm keeps the rough
  // registration's tau_dist (Eq. (9)) inliers and near outliers while
  // dropping hits on unrelated surfaces.
  double max_distance = 0.05;
  // Lattice search: half-size of the searched cell block [cells]; the block
  // is (2 window + 1)^2. At the paper's ~1.7 mm spacing, 2 cells reach
  // ~3.4 mm across the surface, enough for CAD samples within a few mm of
  // the scanned surface (correspondence_test measures >= 99% exact nearest).
  int window = 2;
  // true: lattice search (paper Sec. 5.2.1); false: kd-tree over the crop.
  bool use_lattice = true;

  bool IsValid(std::string* error) const;
};

// Optional per-scan, per-cell target weights w_edge (cell index order), as
// the edge detector writes them; nullptr means weight 1 everywhere.
using CellWeights = std::vector<std::vector<float>>;
// Per scan, per cell: 1 marks a cell. The searches take two: `excluded`
// (a covering's cells: a match to one carries weight 0, the sample is left
// out) and `missing` (mixed pixels: taken as if the beam had returned
// nothing, the sample matches its next nearest cell).
using CellMask = std::vector<std::vector<uint8_t>>;

// The weight a match to (scan, cell) carries: 0 when `excluded` marks the
// cell, else its weight (1 without weights); 1 for no match (scan < 0).
inline float CellWeight(const CellWeights* weights, const CellMask* excluded, int scan, int cell) {
  if (scan < 0) return 1.f;
  const size_t s = static_cast<size_t>(scan), c = static_cast<size_t>(cell);
  if (excluded != nullptr && (*excluded)[s][c] != 0) return 0.f;
  return weights != nullptr ? (*weights)[s][c] : 1.f;
}

}  // namespace edgefit

#endif  // EDGEFIT_CORRESPONDENCE_CORRESPONDENCES_H_
