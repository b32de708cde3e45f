// The floor the rough base stages stand the base on (floor_height.h), on a
// virtual scan (3 scanners, 1.7 mm, 1 mm noise) of a round base with a box
// on its side, 0.35 m tall, standing on the floor at z = 0: the floor's
// height within a millimetre, the base's top when a box leaves the floor
// out, and a clear error without a level surface. And a depth camera's
// frames: a far floor, noisy with range squared, against a table top near
// the camera; a ceiling above it.
#include "solvers/base/floor_height.h"

#include <gtest/gtest.h>

#include <utility>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/scanner/depth_camera.h"
#include "solvers/link_scan_test_util.h"

namespace edgefit {
namespace {

const ScanSet& Scans() {
  static const ScanSet* scans = [] {
    return new ScanSet(testing_util::ScanLinkOnFloor(testing_util::RoundBaseWithBox(),
                                                     PoseFromXyzRpy({1.2, -0.4, 0.0}, {0, 0, 0.7}),
                                                     {}, 5)
                           .scans);
  }();
  return *scans;
}

TEST(FloorHeightTest, FindsTheFloor) {
  double floor_z = 1.0;
  ASSERT_TRUE(EstimateFloorHeight(Scans(), Eigen::AlignedBox3d(), FloorOptions(), &floor_z).ok());
  EXPECT_NEAR(floor_z, 0.0, 1e-3);
}

TEST(FloorHeightTest, EveryRowAndColumnAgrees) {
  FloorOptions options;
  options.stride = 1;
  double floor_z = 1.0;
  ASSERT_TRUE(EstimateFloorHeight(Scans(), Eigen::AlignedBox3d(), options, &floor_z).ok());
  EXPECT_NEAR(floor_z, 0.0, 1e-3);
}

TEST(FloorHeightTest, TheRegionLimitsTheSearch) {
  // A box around the base's top only: its top at 0.35 m is the level surface.
  const Eigen::AlignedBox3d top(Eigen::Vector3d(0.8, -0.8, 0.3), Eigen::Vector3d(1.6, 0.0, 0.5));
  double floor_z = 0.0;
  ASSERT_TRUE(EstimateFloorHeight(Scans(), top, FloorOptions(), &floor_z).ok());
  EXPECT_NEAR(floor_z, 0.35, 2e-3);
}

// A 320 x 240 depth camera (fx 300) at `eye` looking at `target`, 1.5 mm
// of depth noise at 1 m growing with depth squared, scanning the floor and
// `other`.
ScanSet CameraFrame(SceneMesh other, const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  Scene scene;
  scene.meshes.push_back(testing_util::Floor());
  scene.meshes.push_back(std::move(other));
  VirtualScanOptions options;
  options.camera.width = 320;
  options.camera.height = 240;
  options.camera.camera.fx = options.camera.camera.fy = 300.0;
  options.camera.camera.cx = 159.5;
  options.camera.camera.cy = 119.5;
  options.camera.sigma_at_1m = 0.0015;
  options.camera.footprint_px = 0.0;
  Pose T_world_camera;
  CHECK(LookAt(eye, target, Eigen::Vector3d::UnitZ(), &T_world_camera));
  VirtualScan scan;
  CHECK(ScanScene(scene, {T_world_camera}, options, &scan).ok());
  return scan.scans;
}

TEST(FloorHeightTest, ADepthCamerasFarNoisyFloorBeatsANearTable) {
  // A camera 1.6 m high looking at the floor 5 m ahead, 1.5 mm of depth
  // noise at 1 m (37 mm at 5 m); a 1 m table top 1.4-2.2 m in front of it
  // (3-8 mm). The floor's level points outnumber the table's, but spread
  // over many 5 mm bins: the table's one bin was the fullest.
  SceneMesh table;
  table.mesh_world.Append(MakeBoxMesh({0.8, 1.2, 1.0}), PoseFromXyzRpy({1.8, 0.0, 0.5}, {0, 0, 0}));
  table.label = kLabelBackground;
  table.kind = "table";
  const ScanSet frame = CameraFrame(std::move(table), {0, 0, 1.6}, {5.0, 0, 0});
  double floor_z = 1.0;
  ASSERT_TRUE(EstimateFloorHeight(frame, Eigen::AlignedBox3d(), FloorOptions(), &floor_z).ok());
  EXPECT_NEAR(floor_z, 0.0, 0.01);
}

TEST(FloorHeightTest, ACeilingAboveTheCameraIsNotTheFloor) {
  // A camera 1.6 m high looking level: the ceiling 0.6 m above it is seen
  // nearer and smoother than the floor 1.6 m below; it faces down, the
  // floor up.
  SceneMesh ceiling = testing_util::Floor();
  for (Eigen::Vector3d& v : ceiling.mesh_world.vertices) v.z() = 2.2;
  ceiling.kind = "ceiling";
  const ScanSet frame = CameraFrame(std::move(ceiling), {0, 0, 1.6}, {5.0, 0, 1.6});
  double floor_z = 1.0;
  ASSERT_TRUE(EstimateFloorHeight(frame, Eigen::AlignedBox3d(), FloorOptions(), &floor_z).ok());
  EXPECT_NEAR(floor_z, 0.0, 0.01);
}

TEST(FloorHeightTest, NoLevelSurfaceIsAnError) {
  const Eigen::AlignedBox3d empty(Eigen::Vector3d(10, 10, 10), Eigen::Vector3d(11, 11, 11));
  double floor_z = 0.0;
  const Status status = EstimateFloorHeight(Scans(), empty, FloorOptions(), &floor_z);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("no horizontal surface"), std::string::npos);
  FloorOptions bad;
  bad.stride = 0;
  EXPECT_FALSE(EstimateFloorHeight(Scans(), Eigen::AlignedBox3d(), bad, &floor_z).ok());
}

}  // namespace
}  // namespace edgefit
