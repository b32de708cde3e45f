// Region growing over the edge candidates of all scans (paper Sec. 4.3).
//
// The candidates (S_i < tau_dot) of every scan are gathered in world
// coordinates into one kd-tree (nanoflann). Seeds are taken in order of
// increasing score S_i (ties by candidate index, so the result never depends
// on threads); from each unassigned seed a region grows breadth first through
// unassigned neighbours k within `radius` of the point being expanded whose
// normals agree with its normal n_current:
//   |n_current . n_k| > tau_region                          (Eq. 5)
// Regions with fewer than tau_min points are discarded as noise; their points
// stay assigned (they neither seed nor join later regions).
#ifndef EDGEFIT_EDGES_REGION_GROWING_H_
#define EDGEFIT_EDGES_REGION_GROWING_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace edgefit {

struct RegionGrowingOptions {
  double radius = 0.004;     // [m] neighbour radius when growing
  double tau_region = 0.95;  // Eq. (5)
  int tau_min = 300;         // [points] smaller regions are noise
};

// The candidates of all scans, in a stable order (scan, then cell).
struct EdgeCandidates {
  std::vector<Eigen::Vector3f> p_world;  // [m]
  std::vector<Eigen::Vector3f> n_world;  // unit normals (4.1) rotated to the world
  std::vector<float> score;              // S_i (Eq. 4)

  size_t size() const { return p_world.size(); }
  void Reserve(size_t n);
  void Add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, float s);
};

struct RegionGrowingResult {
  // Per candidate: index of its valid region (>= tau_min points), or -1.
  std::vector<int32_t> region;
  size_t regions = 0;      // valid regions
  size_t edge_points = 0;  // candidates in valid regions
};

// Grows the regions. The neighbour lists are found in parallel (OpenMP),
// the growing itself is sequential; the result is the same for any thread
// count.
void GrowEdgeRegions(const EdgeCandidates& candidates, const RegionGrowingOptions& options,
                     RegionGrowingResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_EDGES_REGION_GROWING_H_
