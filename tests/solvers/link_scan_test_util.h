// Shared by the solver tests on virtual scans: one link (and optionally
// meshes that are not in its model) on the floor, scanned by the virtual
// scanner from scanners placed 1.5-2.5 m around it.
#ifndef EDGEFIT_TESTS_SOLVERS_LINK_SCAN_TEST_UTIL_H_
#define EDGEFIT_TESTS_SOLVERS_LINK_SCAN_TEST_UTIL_H_

#include <glog/logging.h>

#include <cstdint>
#include <vector>

#include "correspondence/correspondence_test_util.h"
#include "edgefit/core/pose.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/scene.h"

namespace edgefit {
namespace testing_util {

// A round robot base 0.35 m tall with a box on its side (a cable outlet),
// link frame at the centre of the bottom face, z up.
inline TriangleMesh RoundBaseWithBox() {
  TriangleMesh mesh;
  mesh.Append(MakeCylinderMesh(0.30, 0.35, 96), PoseFromXyzRpy({0, 0, 0.175}, {0, 0, 0}));
  mesh.Append(MakeBoxMesh({0.25, 0.20, 0.35}), PoseFromXyzRpy({0.32, 0, 0.175}, {0, 0, 0}));
  return mesh;
}

// Scans the floor, `link_mesh` posed at T_world_link (label: link 0) and
// `others` (world frame, their own labels) with `options` (spacing, noise;
// the asset box is the link's). `placement_seed` seeds the scanner poses.
inline VirtualScan ScanLinkOnFloor(const TriangleMesh& link_mesh, const Pose& T_world_link,
                                   std::vector<SceneMesh> others, uint64_t placement_seed,
                                   VirtualScanOptions options = VirtualScanOptions()) {
  Scene scene;
  scene.meshes.push_back(Floor());
  SceneMesh link;
  link.mesh_world.Append(link_mesh, T_world_link);
  link.label = LinkLabel(0);
  link.link = 0;
  link.kind = "link";
  const Eigen::AlignedBox3d box = link.mesh_world.BoundingBox();
  scene.meshes.push_back(std::move(link));
  for (SceneMesh& m : others) scene.meshes.push_back(std::move(m));
  ScannerPlacementOptions placement;
  placement.min_distance = 1.5;
  placement.max_distance = 2.5;
  placement.seed = placement_seed;
  options.asset_box_world = box;
  VirtualScan scan;
  CHECK(ScanScene(scene, PlaceScanners(box, placement), options, &scan).ok());
  return scan;
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_SOLVERS_LINK_SCAN_TEST_UTIL_H_
