// Closed meshes of the bracket and cover shapes (accessory_parts.h).
#include <glog/logging.h>

#include "accessory_parts.h"

namespace edgefit {
namespace scene_internal {

TriangleMesh MakeLBracketMesh(const Pose& T_world_bracket, double width, double plate,
                              double height, double thickness) {
  CHECK_GT(thickness, 0.0);
  CHECK_GT(plate, thickness);
  CHECK_GT(height, thickness);
  // The L outline in the (y, z) plane, counter-clockwise seen from +x;
  // vertex 3 is the reflex corner, from which a fan covers the whole L.
  const double t = thickness;
  const Eigen::Vector2d outline[6] = {{0, 0}, {plate, 0}, {plate, t}, {t, t}, {t, height},
                                      {0, height}};
  TriangleMesh mesh;
  for (double x : {-width / 2, width / 2}) {
    for (const Eigen::Vector2d& yz : outline) {
      mesh.vertices.push_back(T_world_bracket * Eigen::Vector3d(x, yz.x(), yz.y()));
    }
  }
  const int fan[4][2] = {{4, 5}, {5, 0}, {0, 1}, {1, 2}};
  for (const auto& f : fan) {
    mesh.triangles.emplace_back(6 + 3, 6 + f[0], 6 + f[1]);  // +x cap
    mesh.triangles.emplace_back(3, f[1], f[0]);              // -x cap
  }
  // Sides: edge i -> i+1 of a counter-clockwise outline faces outward.
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    mesh.triangles.emplace_back(i, j, 6 + j);
    mesh.triangles.emplace_back(i, 6 + j, 6 + i);
  }
  return mesh;
}

TriangleMesh MakeHeightFieldSlab(const Pose& T_world_grid, double x0, double y0, double dx,
                                 double dy, int nu, int nv, const std::vector<double>& bottom,
                                 double thickness) {
  CHECK_GE(nu, 1);
  CHECK_GE(nv, 1);
  CHECK_EQ(bottom.size(), static_cast<size_t>((nu + 1) * (nv + 1)));
  TriangleMesh mesh;
  const int layer = (nu + 1) * (nv + 1);
  for (int top = 0; top < 2; ++top) {
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        const double z = bottom[i + j * (nu + 1)] + (top ? thickness : 0.0);
        mesh.vertices.push_back(T_world_grid * Eigen::Vector3d(x0 + i * dx, y0 + j * dy, z));
      }
    }
  }
  auto index = [nu](int i, int j) { return i + j * (nu + 1); };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      // Top faces +z, bottom faces -z.
      mesh.triangles.emplace_back(layer + a, layer + b, layer + c);
      mesh.triangles.emplace_back(layer + a, layer + c, layer + d);
      mesh.triangles.emplace_back(a, c, b);
      mesh.triangles.emplace_back(a, d, c);
    }
  }
  // The boundary loop, counter-clockwise seen from +z, and a wall per edge.
  std::vector<int> loop;
  for (int i = 0; i < nu; ++i) loop.push_back(index(i, 0));
  for (int j = 0; j < nv; ++j) loop.push_back(index(nu, j));
  for (int i = nu; i > 0; --i) loop.push_back(index(i, nv));
  for (int j = nv; j > 0; --j) loop.push_back(index(0, j));
  for (size_t e = 0; e < loop.size(); ++e) {
    const int p = loop[e], q = loop[(e + 1) % loop.size()];
    mesh.triangles.emplace_back(p, q, layer + q);
    mesh.triangles.emplace_back(p, layer + q, layer + p);
  }
  return mesh;
}

}  // namespace scene_internal
}  // namespace edgefit
