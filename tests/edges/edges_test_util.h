// Helpers for the edge tests: small scanned scenes (a wall, a box on a
// floor, a long cylinder) from the virtual scanner, with its labels.
#ifndef EDGEFIT_TESTS_EDGES_EDGES_TEST_UTIL_H_
#define EDGEFIT_TESTS_EDGES_EDGES_TEST_UTIL_H_

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"

namespace edgefit {
namespace edges_test {

inline SceneMesh LinkMesh(const TriangleMesh& mesh, const Pose& T_world_mesh, int link) {
  SceneMesh m;
  m.mesh_world.Append(mesh, T_world_mesh);
  m.label = LinkLabel(link);
  m.link = link;
  m.kind = "link";
  return m;
}

inline SceneMesh FloorMesh(double half = 20.0) {
  SceneMesh m;
  m.mesh_world.vertices = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  m.mesh_world.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.label = kLabelBackground;
  m.kind = "floor";
  return m;
}

// A 1 m x 1 m wall, 5 cm thick, whose front face is the plane x = distance,
// scanned by one scanner at the origin looking along +x.
inline VirtualScan ScanWall(double distance, double noise_sigma) {
  Scene scene;
  scene.meshes.push_back(LinkMesh(MakeBoxMesh({0.05, 1.0, 1.0}),
                                  Pose(Eigen::Translation3d(distance + 0.025, 0, 0)), 0));
  VirtualScanOptions options;
  options.noise_sigma = noise_sigma;
  options.window_margin_deg = 0.0;
  VirtualScan scan;
  EXPECT_TRUE(ScanScene(scene, {Pose::Identity()}, options, &scan).ok());
  return scan;
}

// The box of BoxScene: size and centre (it stands on the floor z = 0).
inline Eigen::Vector3d BoxSize() { return {0.8, 0.6, 0.5}; }
inline Eigen::Vector3d BoxCentre() { return {0.0, 0.0, 0.25}; }

// A box (link 0) on a floor scanned from `scanners` placed around it.
inline VirtualScan ScanBox(double noise_sigma, int scanners, uint64_t seed = 3) {
  Scene scene;
  scene.meshes.push_back(FloorMesh());
  scene.meshes.push_back(
      LinkMesh(MakeBoxMesh(BoxSize()), Pose(Eigen::Translation3d(BoxCentre())), 0));
  Eigen::AlignedBox3d box(BoxCentre() - BoxSize() / 2, BoxCentre() + BoxSize() / 2);
  ScannerPlacementOptions placement;
  placement.count = scanners;
  placement.seed = seed;
  placement.min_distance = 2.0;
  placement.max_distance = 3.0;
  VirtualScanOptions options;
  options.noise_sigma = noise_sigma;
  options.window_margin_deg = 1.0;
  options.seed = seed;
  VirtualScan scan;
  EXPECT_TRUE(ScanScene(scene, PlaceScanners(box, placement), options, &scan).ok());
  return scan;
}

// Distance [m] from the box surface point p_world to the nearest box edge,
// and the outward normal of the face it lies on.
inline double BoxEdgeDistance(const Eigen::Vector3d& p_world, Eigen::Vector3d* face_normal) {
  const Eigen::Vector3d half = BoxSize() / 2;
  const Eigen::Vector3d q = p_world - BoxCentre();
  // The face: the axis where |q| is closest to the half size.
  int axis = 0;
  double best = 1e9;
  for (int a = 0; a < 3; ++a) {
    const double gap = std::abs(half[a] - std::abs(q[a]));
    if (gap < best) best = gap, axis = a;
  }
  *face_normal = Eigen::Vector3d::Zero();
  (*face_normal)[axis] = q[axis] > 0 ? 1.0 : -1.0;
  double edge = 1e9;
  for (int a = 0; a < 3; ++a) {
    if (a != axis) edge = std::min(edge, half[a] - std::abs(q[a]));
  }
  return edge;
}

inline double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 / M_PI;
}

// The q-quantile (0..1) of `values` (copied).
inline double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::nan("");
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace edges_test
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_EDGES_EDGES_TEST_UTIL_H_
