// Test helpers for scene meshes: closedness, finiteness, and how deep a
// point lies inside a mesh (generalized winding number, Jacobson et al.
// 2013, robust to the small holes of CAD STL files).
#ifndef EDGEFIT_TESTS_SCENE_MESH_CHECKS_H_
#define EDGEFIT_TESTS_SCENE_MESH_CHECKS_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "edgefit/model/point_triangle_distance.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {
namespace testing_scene {

inline bool AllFinite(const TriangleMesh& mesh) {
  for (const Eigen::Vector3d& v : mesh.vertices) {
    if (!v.allFinite()) return false;
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if ((t.array() < 0).any() || (t.array() >= static_cast<int>(mesh.vertices.size())).any()) {
      return false;
    }
  }
  return true;
}

// Closed and consistently oriented: every directed edge appears once and
// its reverse once.
inline bool IsClosed(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return !mesh.triangles.empty();
}

// Winding number of the closed (or nearly closed) mesh around p: ~1 inside,
// ~0 outside. Solid angle per triangle after Van Oosterom and Strackee.
inline double WindingNumber(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double total = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - p, b = mesh.vertices[t[1]] - p,
                          c = mesh.vertices[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * M_PI);
}

// Distance from p to triangle abc.
inline double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return std::sqrt(SquaredDistanceToTriangle(p, a, b, c));
}

inline double DistanceToMesh(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double best = INFINITY;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    best = std::min(best, PointTriangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                mesh.vertices[t[2]]));
  }
  return best;
}

// Depth of p inside the mesh [m]: 0 outside, else the distance to the surface.
inline double PenetrationDepth(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  if (!mesh.BoundingBox().contains(p)) return 0.0;
  if (WindingNumber(mesh, p) < 0.5) return 0.0;
  return DistanceToMesh(mesh, p);
}

}  // namespace testing_scene
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SCENE_MESH_CHECKS_H_
