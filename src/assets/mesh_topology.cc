#include "edgefit/assets/mesh_topology.h"

#include <algorithm>
#include <map>
#include <utility>

namespace edgefit {

MeshTopologyReport AnalyzeMeshTopology(const TriangleMesh& mesh) {
  MeshTopologyReport report;
  // Undirected edge (low, high) -> (uses low->high, uses high->low).
  std::map<std::pair<int, int>, std::pair<int, int>> edges;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const bool zero_area =
        (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).squaredNorm() == 0.0;
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || zero_area) {
      ++report.degenerate_triangles;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int u = t[k], v = t[(k + 1) % 3];
      auto& uses = edges[{std::min(u, v), std::max(u, v)}];
      (u < v ? uses.first : uses.second) += 1;
    }
  }
  report.edges = static_cast<int>(edges.size());
  for (const auto& [edge, uses] : edges) {
    const int total = uses.first + uses.second;
    if (total == 1) {
      ++report.open_edges;
    } else if (total > 2) {
      ++report.non_manifold_edges;
    } else if (uses.first != 1) {
      ++report.misoriented_edges;
    }
  }
  return report;
}

double SignedVolume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    six_volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return six_volume / 6.0;
}

}  // namespace edgefit
