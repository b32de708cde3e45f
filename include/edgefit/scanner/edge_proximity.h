// EdgeProximityIndex: "is this point within r of a sharp edge?" in O(1).
//
// Used to flag true-edge cells of a virtual scan (scene.h, kTrueEdgeFlag):
// a noise-free hit is a true-edge point when its distance to the nearest
// sharp CAD edge segment is <= r. The segments are binned in a hash grid of
// cubic cells of side 4 r: each segment is cut into pieces no longer than one
// cell, and every piece is registered in all cells its r-dilated bounding box
// touches. A query looks up the single cell containing the point and
// computes the exact point-to-segment distance to the segments listed
// there, so the answer is exact (no sampling approximation): any segment
// within r of the point has a piece whose dilated box contains the point.
// Points far from every edge (most of a scan) cost one hash lookup.
#ifndef EDGEFIT_SCANNER_EDGE_PROXIMITY_H_
#define EDGEFIT_SCANNER_EDGE_PROXIMITY_H_

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edgefit/model/sharp_edges.h"

namespace edgefit {

class EdgeProximityIndex {
 public:
  EdgeProximityIndex() = default;
  // Indexes `segments` (any frame, [m]) for queries with radius `radius` [m] (> 0).
  EdgeProximityIndex(std::vector<EdgeSegment> segments, double radius);

  bool empty() const { return segments_.empty(); }
  double radius() const { return radius_; }
  size_t segment_count() const { return segments_.size(); }

  // True when some segment lies within radius() of p (same frame as the segments).
  bool Within(const Eigen::Vector3d& p) const;
  // Distance from p to the nearest segment, if it is <= radius(); otherwise
  // returns a value > radius() (not the true distance).
  double NearDistance(const Eigen::Vector3d& p) const;

 private:
  uint64_t CellKey(const Eigen::Vector3d& p) const;
  uint64_t CellKey(int64_t ix, int64_t iy, int64_t iz) const;

  std::vector<EdgeSegment> segments_;
  double radius_ = 0.0;
  double cell_size_ = 1.0;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  // Cell key -> [begin, end) in cell_segments_.
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> cells_;
  std::vector<uint32_t> cell_segments_;
};

// Euclidean distance from p to the segment [a, b] [m].
double PointSegmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b);

}  // namespace edgefit

#endif  // EDGEFIT_SCANNER_EDGE_PROXIMITY_H_
