// Shared by the weighted-ICP tests: an asymmetric link-like mesh (an L of
// two boxes), scans made directly from posed point sets, pose errors.
#ifndef EDGEFIT_TESTS_SOLVERS_ICP_TEST_UTIL_H_
#define EDGEFIT_TESTS_SOLVERS_ICP_TEST_UTIL_H_

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace testing_util {

// An L of two boxes, 0.40 x 0.15 x 0.10 m and 0.10 x 0.15 x 0.30 m, in its
// link frame: no symmetry, so every pose is determined by its surface.
inline TriangleMesh LinkMesh() {
  TriangleMesh mesh;
  mesh.Append(MakeBoxMesh({0.40, 0.15, 0.10}), PoseFromXyzRpy({0.10, 0.0, 0.0}, {0, 0, 0}));
  mesh.Append(MakeBoxMesh({0.10, 0.15, 0.30}), PoseFromXyzRpy({0.25, 0.0, 0.20}, {0, 0, 0}));
  return mesh;
}

// An unorganized one-scan ScanSet holding points_world (scanner = world).
inline ScanSet CloudScan(const std::vector<Eigen::Vector3d>& points_world) {
  ScanSet set;
  OrganizedScan scan(1, static_cast<int>(points_world.size()));
  scan.set_organized(false);
  for (size_t i = 0; i < points_world.size(); ++i) {
    scan.SetPoint(i, points_world[i].cast<float>(), 1.0f);
  }
  set.scans.push_back(std::move(scan));
  set.sources.push_back("synthetic");
  return set;
}

inline double RotationErrorRad(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

inline double TranslationError(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SOLVERS_ICP_TEST_UTIL_H_
