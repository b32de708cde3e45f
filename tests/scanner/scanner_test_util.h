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
#include "edgefit/model/mesh_proximity.h"
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

// "Is p within r of the mesh?": the library's.
using ::edgefit::MeshProximity;

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SCANNER_SCANNER_TEST_UTIL_H_
