#include "edgefit/model/sharp_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace edgefit {

MeshEdges ExtractSharpEdges(const TriangleMesh& mesh, const SharpEdgeOptions& options) {
  MeshEdges out;
  const double cos_threshold = std::cos(options.min_dihedral_deg * M_PI / 180.0);
  std::vector<Eigen::Vector3d> normals;
  normals.reserve(mesh.triangles.size());
  // (edge key = min vertex << 32 | max vertex, triangle), sorted so the
  // triangles of one edge are adjacent.
  std::vector<std::pair<uint64_t, int>> edge_faces;
  edge_faces.reserve(3 * mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d cross = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                                      .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    const double norm = cross.norm();
    normals.push_back(norm > 0.0 ? Eigen::Vector3d(cross / norm) : Eigen::Vector3d::Zero());
    if (!(norm > 0.0)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint64_t u = static_cast<uint32_t>(tri[k]), v = static_cast<uint32_t>(tri[(k + 1) % 3]);
      edge_faces.emplace_back(std::min(u, v) << 32 | std::max(u, v), static_cast<int>(t));
    }
  }
  std::sort(edge_faces.begin(), edge_faces.end());
  for (size_t begin = 0; begin < edge_faces.size();) {
    size_t end = begin + 1;
    while (end < edge_faces.size() && edge_faces[end].first == edge_faces[begin].first) ++end;
    const uint64_t key = edge_faces[begin].first;
    const EdgeSegment segment{mesh.vertices[key >> 32], mesh.vertices[key & 0xFFFFFFFFULL]};
    const size_t count = end - begin;
    if (count == 1) {
      out.boundary.push_back(segment);
    } else {
      if (count > 2) ++out.non_manifold;
      // Smallest normal dot product over all face pairs = largest angle.
      double min_dot = 1.0;
      for (size_t i = begin; i < end; ++i) {
        for (size_t k = i + 1; k < end; ++k) {
          min_dot = std::min(min_dot, normals[edge_faces[i].second].dot(normals[edge_faces[k].second]));
        }
      }
      if (min_dot <= cos_threshold) out.sharp.push_back(segment);
    }
    begin = end;
  }
  return out;
}

}  // namespace edgefit
