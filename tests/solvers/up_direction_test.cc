// Up from the dominant plane (up_direction.h), on a virtual scan (5
// scanners, 1 mm noise) of a round base with a box on its side standing on
// the floor: the floor's normal within a tenth of a degree when the scans'
// poses are level and when they are turned by tens of degrees (a depth
// camera's frame whose pose is not levelled); the levelling rotation takes
// it back to z; a plane beyond the tilt bound is not a floor.
#include "solvers/base/up_direction.h"

#include <gtest/gtest.h>

#include <cmath>

#include "edgefit/core/angles.h"
#include "edgefit/model/primitive_meshes.h"
#include "solvers/link_scan_test_util.h"

namespace edgefit {
namespace {

const ScanSet& LevelScans() {
  static const ScanSet* scans = [] {
    return new ScanSet(testing_util::ScanLinkOnFloor(testing_util::RoundBaseWithBox(),
                                                     PoseFromXyzRpy({1.2, -0.4, 0.0}, {0, 0, 0.7}),
                                                     {}, 5)
                           .scans);
  }();
  return *scans;
}

// The scans with every pose turned by T_turn (a rotation about the origin).
ScanSet Turned(const Pose& T_turn) {
  ScanSet scans = LevelScans();
  for (OrganizedScan& scan : scans.scans) scan.set_T_world_scanner(T_turn * scan.T_world_scanner());
  return scans;
}

TEST(UpDirectionTest, TheFloorOfALevelScanIsZ) {
  UpEstimate up;
  ASSERT_TRUE(EstimateUp(LevelScans(), UpOptions(), &up).ok());
  EXPECT_LT(up.tilt, 0.1 * kDeg);
  EXPECT_GT(up.up.z(), 0.99);
  EXPECT_GT(up.inliers, up.sampled / 2);  // the floor is most of the scan
}

TEST(UpDirectionTest, ATurnedFrameFindsItsFloor) {
  for (const double degrees : {25.0, -40.0}) {
    const Pose T_turn = PoseFromXyzRpy({0, 0, 0}, {degrees * kDeg, 0.3 * degrees * kDeg, 0});
    UpEstimate up;
    ASSERT_TRUE(EstimateUp(Turned(T_turn), UpOptions(), &up).ok());
    const Eigen::Vector3d floor_normal = T_turn.rotation() * Eigen::Vector3d::UnitZ();
    EXPECT_LT(std::acos(std::min(1.0, up.up.dot(floor_normal))), 0.1 * kDeg) << degrees;
    EXPECT_NEAR(up.tilt, std::acos(floor_normal.z()), 0.1 * kDeg);
    EXPECT_TRUE((LevellingRotation(up.up) * up.up).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  }
}

TEST(UpDirectionTest, APlaneBeyondTheTiltBoundIsNoFloor) {
  UpOptions options;
  options.max_tilt = 20.0 * kDeg;
  UpEstimate up;
  const Status status =
      EstimateUp(Turned(PoseFromXyzRpy({0, 0, 0}, {30.0 * kDeg, 0, 0})), options, &up);
  ASSERT_FALSE(status.ok()) << "up " << up.up.transpose();
  EXPECT_NE(status.message().find("no plane"), std::string::npos);
  options.max_tilt = 0.0;
  EXPECT_FALSE(EstimateUp(LevelScans(), options, &up).ok());
}

}  // namespace
}  // namespace edgefit
