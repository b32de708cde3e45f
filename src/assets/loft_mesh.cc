#include "edgefit/assets/loft_mesh.h"

#include <glog/logging.h>

namespace edgefit {
namespace {

// Appends ring vertices; returns the index of its first vertex.
int AddRing(const Ring& ring, TriangleMesh* mesh) {
  const int first = static_cast<int>(mesh->vertices.size());
  mesh->vertices.insert(mesh->vertices.end(), ring.begin(), ring.end());
  return first;
}

// Side triangles between ring a (first index ia, size na) and ring b, with
// the outward normal for rings counter-clockwise about the a -> b direction.
void JoinRings(int ia, int na, int ib, int nb, TriangleMesh* mesh) {
  if (na == 1 && nb == 1) return;
  const int n = std::max(na, nb);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (na == 1) {  // Apex at the start.
      mesh->triangles.emplace_back(ia, ib + j, ib + i);
    } else if (nb == 1) {  // Apex at the end.
      mesh->triangles.emplace_back(ia + i, ia + j, ib);
    } else {
      mesh->triangles.emplace_back(ia + i, ia + j, ib + j);
      mesh->triangles.emplace_back(ia + i, ib + j, ib + i);
    }
  }
}

// Closes a ring with a planar cap facing along +direction (outward = true
// means counter-clockwise as seen from the cap's outside, i.e. the ring's
// own order for the last ring, reversed for the first).
void Cap(int first, const Ring& ring, bool reverse, TriangleMesh* mesh) {
  const int n = static_cast<int>(ring.size());
  if (n == 1) return;
  auto add = [&](int a, int b, int c) {
    if (reverse) {
      mesh->triangles.emplace_back(a, c, b);
    } else {
      mesh->triangles.emplace_back(a, b, c);
    }
  };
  constexpr int kMaxVertexFan = 8;
  if (n <= kMaxVertexFan) {
    for (int i = 1; i + 1 < n; ++i) add(first, first + i, first + i + 1);
    return;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : ring) centroid += v;
  const int centre = static_cast<int>(mesh->vertices.size());
  mesh->vertices.push_back(centroid / n);
  for (int i = 0; i < n; ++i) add(centre, first + i, first + (i + 1) % n);
}

void CheckRings(const std::vector<Ring>& rings, bool closed) {
  CHECK_GE(rings.size(), closed ? 3u : 2u);
  size_t n = 0;
  for (const Ring& ring : rings) n = std::max(n, ring.size());
  CHECK_GE(n, 3u);
  for (size_t k = 0; k < rings.size(); ++k) {
    const bool end = !closed && (k == 0 || k + 1 == rings.size());
    CHECK(rings[k].size() == n || (end && rings[k].size() == 1))
        << "loft ring " << k << " has " << rings[k].size() << " vertices, expected " << n;
  }
}

}  // namespace

TriangleMesh MakeLoftMesh(const std::vector<Ring>& rings) {
  CheckRings(rings, /*closed=*/false);
  TriangleMesh mesh;
  std::vector<int> first(rings.size());
  for (size_t k = 0; k < rings.size(); ++k) first[k] = AddRing(rings[k], &mesh);
  for (size_t k = 0; k + 1 < rings.size(); ++k) {
    JoinRings(first[k], static_cast<int>(rings[k].size()), first[k + 1],
              static_cast<int>(rings[k + 1].size()), &mesh);
  }
  Cap(first.front(), rings.front(), /*reverse=*/true, &mesh);
  Cap(first.back(), rings.back(), /*reverse=*/false, &mesh);
  return mesh;
}

TriangleMesh MakeClosedLoftMesh(const std::vector<Ring>& rings) {
  CheckRings(rings, /*closed=*/true);
  TriangleMesh mesh;
  std::vector<int> first(rings.size());
  for (size_t k = 0; k < rings.size(); ++k) first[k] = AddRing(rings[k], &mesh);
  const int n = static_cast<int>(rings[0].size());
  for (size_t k = 0; k < rings.size(); ++k) {
    JoinRings(first[k], n, first[(k + 1) % rings.size()], n, &mesh);
  }
  return mesh;
}

}  // namespace edgefit
