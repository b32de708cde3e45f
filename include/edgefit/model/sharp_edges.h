// Sharp edges of a triangle mesh: the CAD edges a laser scan shows as
// creases, used to weight model points near edges (paper Sec. 4, Eq. 6).
// An interior edge is sharp when the angle between its two face normals
// (0 for a flat surface, 90 deg on a box) is at least the threshold. Edges
// with one face are open boundaries, reported separately. Needs shared
// (welded) vertices: see WeldIdenticalVertices.
#ifndef EDGEFIT_MODEL_SHARP_EDGES_H_
#define EDGEFIT_MODEL_SHARP_EDGES_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct EdgeSegment {
  Eigen::Vector3d a, b;  // End points in the mesh frame [m].
};

struct SharpEdgeOptions {
  double min_dihedral_deg = 30.0;  // [deg] normal angle at or above which an edge is sharp.
};

struct MeshEdges {
  std::vector<EdgeSegment> sharp;     // Interior edges at or above the threshold.
  std::vector<EdgeSegment> boundary;  // Edges of exactly one triangle.
  // Edges shared by more than two triangles; included in `sharp` when any
  // pair of their faces meets the threshold.
  int non_manifold = 0;
};

// Zero-area triangles are ignored (their normal is undefined).
MeshEdges ExtractSharpEdges(const TriangleMesh& mesh, const SharpEdgeOptions& options = {});

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_SHARP_EDGES_H_
