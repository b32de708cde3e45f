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

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
inline double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * vb * denom + ac * vc * denom)).norm();
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
