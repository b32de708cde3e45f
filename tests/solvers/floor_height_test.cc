// The floor the rough base stages stand the base on (floor_height.h), on a
// virtual scan (3 scanners, 1.7 mm, 1 mm noise) of a round base with a box
// on its side, 0.35 m tall, standing on the floor at z = 0: the floor's
// height within a millimetre, the base's top when a box leaves the floor
// out, and a clear error without a level surface.
#include "solvers/base/floor_height.h"

#include <gtest/gtest.h>

#include "edgefit/model/primitive_meshes.h"
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
