// Exact nearest scan point by a nanoflann kd-tree over the valid world points
// of all scans inside a crop box (e.g. the posed link's box plus a margin):
// the 3D reference the lattice search (lattice_search.h) is measured against,
// and the search for unorganized clouds.
//
// The tree is rebuilt only when the crop box (or nothing before) changes, so
// ICP iterations of one link reuse it. Gating and weights as for the lattice
// search; ties between equidistant points follow the tree (rare with noise).
#ifndef EDGEFIT_CORRESPONDENCE_KDTREE_SEARCH_H_
#define EDGEFIT_CORRESPONDENCE_KDTREE_SEARCH_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <vector>

#include "edgefit/correspondence/correspondences.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

class KdTreeSearch {
 public:
  // `scans`, `weights` (nullptr: weight 1), `excluded` (nullptr: none;
  // a marked cell matches with weight 0) and `missing` (nullptr: none; a
  // marked cell is not in the tree) are borrowed and must outlive the
  // searcher.
  KdTreeSearch(const ScanSet* scans, const CellWeights* weights, const CellMask* excluded = nullptr,
               const CellMask* missing = nullptr);
  ~KdTreeSearch();
  KdTreeSearch(const KdTreeSearch&) = delete;
  KdTreeSearch& operator=(const KdTreeSearch&) = delete;

  // (Re)builds the tree over the valid points inside crop_world unless it
  // already holds exactly that crop. Returns true when it rebuilt.
  bool SetCrop(const Eigen::AlignedBox3d& crop_world);

  // SetCrop(crop_world), then replaces *out with the gated nearest points of
  // q_world, ordered by source index. Uses options.max_distance only.
  void Find(const std::vector<Eigen::Vector3f>& q_world, const Eigen::AlignedBox3d& crop_world,
            const CorrespondenceOptions& options, std::vector<Correspondence>* out);

  // Points in the current tree.
  size_t size() const { return points_world_.size(); }

 private:
  struct Tree;
  const ScanSet* scans_;
  const CellWeights* weights_;
  const CellMask* excluded_;
  const CellMask* missing_;
  Eigen::AlignedBox3d crop_world_;
  bool built_ = false;
  std::vector<Eigen::Vector3f> points_world_;  // valid points inside the crop
  std::vector<int> scan_of_;                   // per tree point
  std::vector<int> cell_of_;                   // per tree point
  std::unique_ptr<Tree> tree_;
  std::vector<Correspondence> best_;  // per query; kept between calls
};

}  // namespace edgefit

#endif  // EDGEFIT_CORRESPONDENCE_KDTREE_SEARCH_H_
