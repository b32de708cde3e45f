// Nearest scan point by the scan's angular lattice (paper Sec. 4.1, 5.2.1).
//
// Per query q_world and scan s:
//   q_scanner = T_scanner_world(s) * q_world;
//   (row, col) = ProjectToCell(q_scanner)         (O(1), scan_lattice.h);
//   nearest valid cell in rows [row - w, row + w] x cols [col - w, col + w]
//   (columns wrap on a full-circle scan), by 3D distance in the scanner frame.
// The best over all scans wins (ties: lower scan, then lower cell index), then
// the max_distance gate. Distances are rigid-motion invariant, so comparing
// in each scanner frame needs no world-frame copy of the scans.
//
// Limits, by construction a subset of the exact search (never closer than the
// true nearest point):
//   - a query outside a scan's angular window (behind a windowed scanner,
//     above the top row, at the scanner origin) gets nothing from that scan;
//   - a query on a surface the scanner did not see projects onto the occluder
//     in front of it; the block then holds occluder points, usually beyond
//     max_distance, while the true nearest point may be elsewhere;
//   - unorganized scans (organized() false) or scans without a valid lattice
//     are skipped.
#ifndef EDGEFIT_CORRESPONDENCE_LATTICE_SEARCH_H_
#define EDGEFIT_CORRESPONDENCE_LATTICE_SEARCH_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/correspondence/correspondences.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

class LatticeSearch {
 public:
  // `scans`, `weights` (nullptr: weight 1), `excluded` (nullptr: none;
  // a marked cell matches with weight 0) and `missing` (nullptr: none; a
  // marked cell is never matched) are borrowed and must outlive the
  // searcher; weights[s] and the masks' [s] must have scans[s].size()
  // entries.
  LatticeSearch(const ScanSet* scans, const CellWeights* weights,
                const CellMask* excluded = nullptr, const CellMask* missing = nullptr);

  // Replaces *out with the gated matches of q_world, ordered by source index
  // (deterministic for any thread count). Uses options.window and
  // options.max_distance; ignores use_lattice.
  void Find(const std::vector<Eigen::Vector3f>& q_world, const CorrespondenceOptions& options,
            std::vector<Correspondence>* out);
  // The same within scan `only_scan` alone (-1: every scan, as Find).
  void FindIn(int only_scan, const std::vector<Eigen::Vector3f>& q_world,
              const CorrespondenceOptions& options, std::vector<Correspondence>* out);

  // One query: its nearest cell within `window`, gated by max_d2 = squared
  // max_distance [m^2] (scan = -1 beyond; source left 0). Thread-safe.
  Correspondence Nearest(const Eigen::Vector3f& q_world, int window, float max_d2) const;
  // The same within scan `only_scan` alone (-1: every scan, as Nearest).
  Correspondence NearestIn(int only_scan, const Eigen::Vector3f& q_world, int window,
                           float max_d2) const;

 private:
  const ScanSet* scans_;
  const CellWeights* weights_;
  const CellMask* excluded_;
  const CellMask* missing_;
  std::vector<Eigen::Matrix<double, 3, 4>> T_scanner_world_;  // per scan, [R | t]
  std::vector<bool> searchable_;                              // per scan
  std::vector<Correspondence> best_;                          // per query; kept between calls (ICP)
};

}  // namespace edgefit

#endif  // EDGEFIT_CORRESPONDENCE_LATTICE_SEARCH_H_
