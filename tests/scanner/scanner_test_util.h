// Helpers for the scanner tests: small scenes and exact point-to-mesh checks.
#ifndef EDGEFIT_TESTS_SCANNER_SCANNER_TEST_UTIL_H_
#define EDGEFIT_TESTS_SCANNER_SCANNER_TEST_UTIL_H_

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scene/scene.h"

namespace edgefit {
namespace testing_util {

// A floor quad at z = 0 spanning [-half, half]^2 [m], normal +z.
inline SceneMesh FloorMesh(double half = 20.0) {
  SceneMesh m;
  m.mesh_world.vertices = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  m.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.label = kLabelBackground;
  m.kind = "floor";
  return m;
}

// Closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
inline Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// "Is p within r of the mesh?", exactly, through a hash grid of triangles
// (each registered in every cell its r-dilated box touches).
class MeshProximity {
 public:
  MeshProximity(const TriangleMesh& mesh, double r, double cell = 0.01)
      : mesh_(mesh), r_(r), cell_(cell) {
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      Eigen::AlignedBox3d box;
      for (int k = 0; k < 3; ++k) box.extend(mesh.vertices[mesh.triangles[t][k]]);
      const Eigen::Vector3d lo = ((box.min().array() - r) / cell).floor();
      const Eigen::Vector3d hi = ((box.max().array() + r) / cell).floor();
      for (int64_t x = lo.x(); x <= hi.x(); ++x)
        for (int64_t y = lo.y(); y <= hi.y(); ++y)
          for (int64_t z = lo.z(); z <= hi.z(); ++z) cells_[Key(x, y, z)].push_back(t);
    }
  }
  bool Within(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d c = (p / cell_).array().floor();
    const auto it = cells_.find(Key(c.x(), c.y(), c.z()));
    if (it == cells_.end()) return false;
    for (size_t t : it->second) {
      const Eigen::Vector3i& tri = mesh_.triangles[t];
      const Eigen::Vector3d q = ClosestPointOnTriangle(p, mesh_.vertices[tri[0]],
                                                       mesh_.vertices[tri[1]],
                                                       mesh_.vertices[tri[2]]);
      if ((q - p).norm() <= r_) return true;
    }
    return false;
  }

 private:
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    return (static_cast<uint64_t>(x + (1 << 20)) << 42) ^
           (static_cast<uint64_t>(y + (1 << 20)) << 21) ^ static_cast<uint64_t>(z + (1 << 20));
  }
  const TriangleMesh& mesh_;
  double r_, cell_;
  std::unordered_map<uint64_t, std::vector<size_t>> cells_;
};

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SCANNER_SCANNER_TEST_UTIL_H_
