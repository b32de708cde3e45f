// Height map and convex tips (paper Sec. 6.1, Eq. 11-13) on synthetic
// points: a cone's apex is a tip wherever it falls in its cell; a box's
// corners, a ridge and a stray point in the air are not.
#include "solvers/base/height_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace edgefit {
namespace {

// A 1 m x 1 m floor at z = 0 sampled every 2 mm, with `shape` giving the
// height above the floor at (x, y) (0: floor).
template <typename Shape>
HeightMap MapOf(const Shape& shape, double cell = 0.01) {
  HeightMap map;
  EXPECT_TRUE(HeightMap::Create(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                                cell, &map)
                  .ok());
  int k = 0;
  for (double x = 0.0; x <= 1.0; x += 0.002) {
    for (double y = 0.0; y <= 1.0; y += 0.002) map.Add(Eigen::Vector3d(x, y, shape(x, y)), k++);
  }
  return map;
}

// A locating pin: a cone of radius 0.02 and height 0.03 on a 0.2 m post.
double Pin(double x, double y, const Eigen::Vector2d& apex) {
  const double r = (Eigen::Vector2d(x, y) - apex).norm();
  return r < 0.02 ? 0.2 + 0.03 * (1.0 - r / 0.02) : (r < 0.03 ? 0.2 : 0.0);
}

TEST(HeightMap, FindsAConeApexAnywhereInItsCell) {
  // The apex at a cell's centre, at its border and at its corner.
  for (const Eigen::Vector2d& apex :
       {Eigen::Vector2d(0.305, 0.405), Eigen::Vector2d(0.3, 0.405), Eigen::Vector2d(0.3, 0.4)}) {
    const HeightMap map = MapOf([&](double x, double y) { return Pin(x, y, apex); });
    const std::vector<HeightMap::Tip> tips = map.ConvexTips(ConvexTipOptions());
    ASSERT_EQ(tips.size(), 1u) << apex.transpose();
    EXPECT_LT((tips[0].p.head<2>() - apex).norm(), 0.003) << apex.transpose();
    EXPECT_NEAR(tips[0].p.z(), 0.23, 0.004);
    EXPECT_GE(tips[0].source, 0);
  }
}

TEST(HeightMap, BoxCornersAndRidgesAreNoTips) {
  const HeightMap map = MapOf([](double x, double y) {
    const bool in_box = x > 0.2 && x < 0.5 && y > 0.3 && y < 0.6;
    const bool on_ridge = std::abs(x - 0.7) < 0.004 && y > 0.2 && y < 0.8;  // a thin wall
    return in_box ? 0.3 : (on_ridge ? 0.5 : 0.0);
  });
  // Eq. (13) alone holds at each box corner; the ring test rejects them.
  EXPECT_TRUE(map.ConvexTips(ConvexTipOptions()).empty());
}

TEST(HeightMap, AStrayPointWithEmptySurroundingsIsNoTip) {
  // Only points high above the floor enter the map (FitConveyanceBaseRough):
  // a stray point in the air has no neighbours.
  HeightMap map;
  ASSERT_TRUE(HeightMap::Create(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                                0.01, &map)
                  .ok());
  map.Add(Eigen::Vector3d(0.5, 0.5, 1.0), 7);
  EXPECT_TRUE(map.ConvexTips(ConvexTipOptions()).empty());
  ConvexTipOptions loose;
  loose.min_neighbours = 0;
  const std::vector<HeightMap::Tip> tips = map.ConvexTips(loose);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_EQ(tips[0].source, 7);
}

TEST(HeightMap, TwoNearTipsKeepTheHigherOne) {
  const HeightMap map = MapOf([](double x, double y) {
    return std::max(Pin(x, y, {0.3, 0.3}), Pin(x, y, {0.36, 0.3}) + 0.01);  // 6 cm apart
  });
  ConvexTipOptions apart;
  apart.separation = 0.08;
  const std::vector<HeightMap::Tip> tips = map.ConvexTips(apart);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_NEAR(tips[0].p.x(), 0.36, 0.003);
  EXPECT_EQ(map.ConvexTips(ConvexTipOptions()).size(), 2u);  // 5 cm
}

TEST(HeightMap, RefusesAGridTooLargeAndBadOptions) {
  HeightMap map;
  const Status status = HeightMap::Create(
      Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(500, 500)), 0.01, &map);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("500.0 x 500.0 m"), std::string::npos) << status.message();
  EXPECT_FALSE(HeightMap::Create(Eigen::AlignedBox2d(), 0.01, &map).ok());
  ConvexTipOptions bad;
  bad.min_neighbours = 9;
  EXPECT_FALSE(bad.IsValid(nullptr));
}

}  // namespace
}  // namespace edgefit
