// CorrespondenceSearch: the one object the registration stages hold for a
// scan set; it dispatches on CorrespondenceOptions::use_lattice to the
// lattice search (paper Sec. 5.2.1) or the cropped kd-tree, keeping both
// searchers' buffers (and the kd-tree) between ICP iterations.
#ifndef EDGEFIT_CORRESPONDENCE_CORRESPONDENCE_SEARCH_H_
#define EDGEFIT_CORRESPONDENCE_CORRESPONDENCE_SEARCH_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "edgefit/correspondence/correspondences.h"
#include "edgefit/correspondence/kdtree_search.h"
#include "edgefit/correspondence/lattice_search.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

class CorrespondenceSearch {
 public:
  // Borrowed; see LatticeSearch / KdTreeSearch.
  CorrespondenceSearch(const ScanSet* scans, const CellWeights* weights,
                       const CellMask* excluded = nullptr, const CellMask* missing = nullptr)
      : lattice_(scans, weights, excluded, missing), kdtree_(scans, weights, excluded, missing) {}

  // Matches of q_world (world frame [m]) ordered by source index. crop_world
  // bounds the kd-tree (ignored by the lattice search, which needs no crop).
  // CHECK-fails on invalid options.
  void Find(const std::vector<Eigen::Vector3f>& q_world, const Eigen::AlignedBox3d& crop_world,
            const CorrespondenceOptions& options, std::vector<Correspondence>* out);

  // The lattice searcher, for per-query use (LatticeSearch::Nearest).
  const LatticeSearch& lattice() const { return lattice_; }

 private:
  LatticeSearch lattice_;
  KdTreeSearch kdtree_;
};

}  // namespace edgefit

#endif  // EDGEFIT_CORRESPONDENCE_CORRESPONDENCE_SEARCH_H_
