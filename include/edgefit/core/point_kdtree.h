// A nanoflann kd-tree over a borrowed vector of points: the dataset adaptor
// and index type every exact nearest-point search of edgefit builds on.
#ifndef EDGEFIT_CORE_POINT_KDTREE_H_
#define EDGEFIT_CORE_POINT_KDTREE_H_

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <nanoflann.hpp>
#include <vector>

namespace edgefit {

// nanoflann's dataset interface over *points (borrowed; it must outlive
// the tree and not change while the tree is used).
struct PointVectorAdaptor {
  const std::vector<Eigen::Vector3f>* points;
  size_t kdtree_get_point_count() const { return points->size(); }
  float kdtree_get_pt(size_t i, size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

// Squared Euclidean distances, uint32_t indices; build with
// PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16)).
using PointKdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointVectorAdaptor>,
                                        PointVectorAdaptor, 3, uint32_t>;

}  // namespace edgefit

#endif  // EDGEFIT_CORE_POINT_KDTREE_H_
