// Topology checks for generated meshes: a closed, consistently oriented
// surface has every undirected edge in exactly two triangles, traversed in
// opposite directions.
#ifndef EDGEFIT_ASSETS_MESH_TOPOLOGY_H_
#define EDGEFIT_ASSETS_MESH_TOPOLOGY_H_

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct MeshTopologyReport {
  int edges = 0;              // undirected edges.
  int open_edges = 0;         // in one triangle.
  int non_manifold_edges = 0; // in three or more.
  int misoriented_edges = 0;  // in two triangles traversed the same way.
  int degenerate_triangles = 0;  // repeated index or zero area.

  bool IsClosedAndOriented() const {
    return open_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0 &&
           degenerate_triangles == 0;
  }
};

// By vertex index: weld first (WeldIdenticalVertices) for meshes read from STL.
MeshTopologyReport AnalyzeMeshTopology(const TriangleMesh& mesh);

// Signed volume [m^3] (divergence theorem); positive for an outward-oriented
// closed mesh.
double SignedVolume(const TriangleMesh& mesh);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_MESH_TOPOLOGY_H_
