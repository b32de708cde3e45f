// "Is p within r of the mesh?", exactly, for many points: the mesh's
// triangles in a uniform hash grid, each listed in every cell its box grown
// by the largest reach asked touches, so that one cell lists every triangle
// within that reach of a point in it; the distance to each is the exact
// point-triangle distance (point_triangle_distance.h).
#ifndef EDGEFIT_MODEL_MESH_PROXIMITY_H_
#define EDGEFIT_MODEL_MESH_PROXIMITY_H_

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

class MeshProximity {
 public:
  // `mesh` (borrowed; it must outlive this), `reach`: the largest distance
  // asked [m]; `cell`: the grid's cell [m].
  MeshProximity(const TriangleMesh& mesh, double reach, double cell = 0.01);

  // Whether p lies within `reach` (at most the constructor's) of a triangle.
  bool Within(const Eigen::Vector3d& p, double reach) const;
  bool Within(const Eigen::Vector3d& p) const { return Within(p, reach_); }

 private:
  uint64_t KeyOf(const Eigen::Vector3d& p) const;

  const TriangleMesh& mesh_;
  double reach_, cell_;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_MESH_PROXIMITY_H_
