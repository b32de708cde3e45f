#include "edgefit/model/primitive_meshes.h"

#include <glog/logging.h>

#include <cmath>
#include <map>
#include <utility>

namespace edgefit {

TriangleMesh MakeBoxMesh(const Eigen::Vector3d& size) {
  TriangleMesh mesh;
  const Eigen::Vector3d h = 0.5 * size;
  for (int i = 0; i < 8; ++i) {  // Bit 0: x, bit 1: y, bit 2: z sign.
    mesh.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                               (i & 4) ? h.z() : -h.z());
  }
  // Two triangles per face, counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6},   // -z, +z
                           {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                           {0, 4, 6, 2}, {1, 3, 7, 5}};  // -x, +x
  for (const auto& q : quads) {
    mesh.triangles.emplace_back(q[0], q[1], q[2]);
    mesh.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

TriangleMesh MakeCylinderMesh(double radius, double length, int segments) {
  CHECK_GE(segments, 3);
  TriangleMesh mesh;
  const double z = 0.5 * length;
  for (int i = 0; i < segments; ++i) {  // Vertex 2i bottom rim, 2i+1 top rim.
    const double a = 2.0 * M_PI * i / segments;
    mesh.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), -z);
    mesh.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
  }
  const int bottom = 2 * segments, top = 2 * segments + 1;
  mesh.vertices.emplace_back(0.0, 0.0, -z);
  mesh.vertices.emplace_back(0.0, 0.0, z);
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    const int b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * j, t1 = 2 * j + 1;
    mesh.triangles.emplace_back(b0, b1, t1);
    mesh.triangles.emplace_back(b0, t1, t0);
    mesh.triangles.emplace_back(bottom, b1, b0);
    mesh.triangles.emplace_back(top, t0, t1);
  }
  return mesh;
}

TriangleMesh MakeSphereMesh(double radius, int subdivisions) {
  CHECK_GE(subdivisions, 0);
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {
      {-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Eigen::Vector3d& p : v) p.normalize();
  std::vector<Eigen::Vector3i> f = {
      {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
      {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoint;  // Shared so edges stay welded.
    auto mid = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      const int index = static_cast<int>(v.size()) - 1;
      midpoint.emplace(key, index);
      return index;
    };
    std::vector<Eigen::Vector3i> next;
    next.reserve(4 * f.size());
    for (const Eigen::Vector3i& tri : f) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      next.emplace_back(tri[0], ab, ca);
      next.emplace_back(tri[1], bc, ab);
      next.emplace_back(tri[2], ca, bc);
      next.emplace_back(ab, bc, ca);
    }
    f = std::move(next);
  }
  TriangleMesh mesh;
  for (const Eigen::Vector3d& p : v) mesh.vertices.push_back(radius * p);
  mesh.triangles = std::move(f);
  return mesh;
}

}  // namespace edgefit
