// A triangle mesh as FCL collision geometry (Debian's libfcl): a bounding
// volume hierarchy of oriented boxes and swept spheres (OBBRSS), which FCL
// queries for distance and contact between two meshes. FCL's types stay in
// fcl_mesh.cc.
#ifndef EDGEFIT_WORLD_FCL_MESH_H_
#define EDGEFIT_WORLD_FCL_MESH_H_

#include <Eigen/Geometry>
#include <limits>
#include <memory>

#include "edgefit/core/pose.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

class FclMesh {
 public:
  // The hierarchy of `mesh` (in its own frame; not empty), built by the
  // first query: a mesh never queried costs only its copy.
  explicit FclMesh(const TriangleMesh& mesh);
  ~FclMesh();
  FclMesh(const FclMesh&) = delete;
  FclMesh& operator=(const FclMesh&) = delete;

  // The least distance [m] between this mesh posed by T_world_this and
  // `other` posed by T_world_other: 0 when their surfaces touch or cross.
  // Surfaces only: a mesh wholly inside a closed other one is at the
  // distance between the two surfaces. Sought only below `bound` [m]: a
  // distance beyond it is returned as `bound`, sooner (FCL's traversal
  // drops what cannot come nearer).
  double Distance(const Pose& T_world_this, const FclMesh& other, const Pose& T_world_other,
                  double bound = std::numeric_limits<double>::infinity()) const;

  // Whether this posed surface touches or crosses the (solid) box.
  bool CollidesBox(const Pose& T_world_this, const Eigen::AlignedBox3d& box_world) const;

  // Whether the two posed surfaces touch or cross (cheaper than Distance);
  // *p_world (may be null): a point where they do, the one nearest both
  // surfaces among FCL's contact points and the nearest points of their
  // triangles' corners (FCL's own lies off both where coplanar triangles
  // overlap, as voxel faces do).
  bool Collides(const Pose& T_world_this, const FclMesh& other, const Pose& T_world_other,
                Eigen::Vector3d* p_world = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_FCL_MESH_H_
