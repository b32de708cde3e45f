#include "edgefit/model/triangle_mesh.h"

#include <algorithm>
#include <numeric>

namespace edgefit {

void TriangleMesh::Append(const TriangleMesh& other, const Eigen::Isometry3d& T_this_other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.reserve(vertices.size() + other.vertices.size());
  for (const Eigen::Vector3d& v : other.vertices) vertices.push_back(T_this_other * v);
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const Eigen::Vector3i& t : other.triangles) {
    triangles.push_back(t + Eigen::Vector3i::Constant(offset));
  }
}

Eigen::AlignedBox3d TriangleMesh::BoundingBox(const Eigen::Isometry3d& T_frame_mesh) const {
  Eigen::AlignedBox3d box;  // Default-constructed box is empty.
  for (const Eigen::Vector3d& v : vertices) box.extend(T_frame_mesh * v);
  return box;
}

double TriangleMesh::SurfaceArea() const {
  double area = 0.0;
  for (const Eigen::Vector3i& t : triangles) {
    const Eigen::Vector3d& a = vertices[t[0]];
    area += 0.5 * (vertices[t[1]] - a).cross(vertices[t[2]] - a).norm();
  }
  return area;
}

int WeldIdenticalVertices(TriangleMesh* mesh) {
  const std::vector<Eigen::Vector3d>& v = mesh->vertices;
  // Sort vertex indices lexicographically by coordinates; equal runs merge
  // into their first member. O(n log n), exact comparison on purpose: STL
  // corners shared by neighbouring triangles are written bit-identically.
  std::vector<int> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&v](int a, int b) {
    if (v[a].x() != v[b].x()) return v[a].x() < v[b].x();
    if (v[a].y() != v[b].y()) return v[a].y() < v[b].y();
    if (v[a].z() != v[b].z()) return v[a].z() < v[b].z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> new_index(v.size(), -1);
  std::vector<Eigen::Vector3d> welded;
  welded.reserve(v.size());
  for (size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || v[order[i]] != v[order[i - 1]]) welded.push_back(v[order[i]]);
    new_index[order[i]] = static_cast<int>(welded.size()) - 1;
  }
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(mesh->triangles.size());
  int dropped = 0;
  for (const Eigen::Vector3i& t : mesh->triangles) {
    const Eigen::Vector3i w(new_index[t[0]], new_index[t[1]], new_index[t[2]]);
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
      ++dropped;
      continue;
    }
    triangles.push_back(w);
  }
  mesh->vertices = std::move(welded);
  mesh->triangles = std::move(triangles);
  return dropped;
}

}  // namespace edgefit
