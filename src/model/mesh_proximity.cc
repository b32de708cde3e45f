#include "edgefit/model/mesh_proximity.h"

#include <Eigen/Geometry>
#include <cmath>

#include "edgefit/model/point_triangle_distance.h"

namespace edgefit {
namespace {

// A cell as one key, 21 bits an axis (+-2^20 cells).
uint64_t Key(int64_t x, int64_t y, int64_t z) {
  constexpr int64_t kOffset = int64_t{1} << 20;
  constexpr uint64_t kMask = (uint64_t{1} << 21) - 1;
  return (static_cast<uint64_t>(x + kOffset) & kMask) << 42 | (static_cast<uint64_t>(y + kOffset) & kMask) << 21 |
         (static_cast<uint64_t>(z + kOffset) & kMask);
}

}  // namespace

MeshProximity::MeshProximity(const TriangleMesh& mesh, double reach, double cell)
    : mesh_(mesh), reach_(reach), cell_(cell) {
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    Eigen::AlignedBox3d box;
    for (int k = 0; k < 3; ++k) box.extend(mesh.vertices[static_cast<size_t>(mesh.triangles[t][k])]);
    const Eigen::Array3d lo = ((box.min().array() - reach) / cell).floor();
    const Eigen::Array3d hi = ((box.max().array() + reach) / cell).floor();
    for (int64_t x = static_cast<int64_t>(lo.x()); x <= static_cast<int64_t>(hi.x()); ++x) {
      for (int64_t y = static_cast<int64_t>(lo.y()); y <= static_cast<int64_t>(hi.y()); ++y) {
        for (int64_t z = static_cast<int64_t>(lo.z()); z <= static_cast<int64_t>(hi.z()); ++z) {
          cells_[Key(x, y, z)].push_back(static_cast<uint32_t>(t));
        }
      }
    }
  }
}

uint64_t MeshProximity::KeyOf(const Eigen::Vector3d& p) const {
  const Eigen::Array3d c = (p.array() / cell_).floor();
  return Key(static_cast<int64_t>(c.x()), static_cast<int64_t>(c.y()), static_cast<int64_t>(c.z()));
}

bool MeshProximity::Within(const Eigen::Vector3d& p, double reach) const {
  const auto it = cells_.find(KeyOf(p));
  if (it == cells_.end()) return false;
  for (const uint32_t t : it->second) {
    const Eigen::Vector3i& f = mesh_.triangles[t];
    if (SquaredDistanceToTriangle(p, mesh_.vertices[static_cast<size_t>(f[0])], mesh_.vertices[static_cast<size_t>(f[1])],
                                  mesh_.vertices[static_cast<size_t>(f[2])]) <= reach * reach) {
      return true;
    }
  }
  return false;
}

}  // namespace edgefit
