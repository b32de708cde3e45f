// TriangleMesh: an indexed triangle mesh in one frame (a link frame once
// loaded into a KinematicModel). Lengths in metres.
#ifndef EDGEFIT_MODEL_TRIANGLE_MESH_H_
#define EDGEFIT_MODEL_TRIANGLE_MESH_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace edgefit {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;  // vertex indices, counter-clockwise outward

  bool empty() const { return triangles.empty(); }
  // Appends `other` transformed by T_this_other.
  void Append(const TriangleMesh& other,
              const Eigen::Isometry3d& T_this_other = Eigen::Isometry3d::Identity());
  // Axis-aligned bounding box of the vertices after T_frame_mesh; empty box if no vertices.
  Eigen::AlignedBox3d BoundingBox(
      const Eigen::Isometry3d& T_frame_mesh = Eigen::Isometry3d::Identity()) const;
  double SurfaceArea() const;
};

// Merges vertices with bit-identical coordinates (STL stores each triangle's
// corners separately; welding makes neighbouring triangles share edges) and
// drops triangles that become degenerate (two equal indices). Returns the
// number of triangles dropped.
int WeldIdenticalVertices(TriangleMesh* mesh);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_TRIANGLE_MESH_H_
