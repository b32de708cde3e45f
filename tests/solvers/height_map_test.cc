// Height map and convex tips (paper Sec. 6.1, Eq. 11-13) on synthetic
// points: a cone's apex is a tip wherever it falls in its cell; a box's
// corners, a ridge and a stray point in the air are not; returns hanging
// above a surface (mixed pixels) are no tips of a corroborated map.
#include "solvers/base/height_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
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

// Mixed pixels behind a pin's edge: two returns per 1 cm cell along a strip
// beside the post, at heights between the plate's and above the apex.
TEST(HeightMap, ReturnsHangingAboveASurfaceAreNoTipsOfACorroboratedMap) {
  const Eigen::Vector2d apex(0.305, 0.405);
  std::vector<Eigen::Vector3d> points;
  for (double x = 0.0; x <= 1.0; x += 0.002) {
    for (double y = 0.0; y <= 1.0; y += 0.002) {
      points.emplace_back(x, y, 0.1 + Pin(x, y, apex));  // on a plate 0.1 m high
    }
  }
  for (int k = 0; k < 40; ++k) {
    const double x = 0.355 + 0.01 * k, z = 0.12 + 0.003 * (k % 7) * (k % 5);
    points.emplace_back(x, 0.403, z);
    points.emplace_back(x, 0.406, z + 0.004 + 0.001 * (k % 3));
  }
  const Eigen::AlignedBox2d extent(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
  HeightMap plain, corroborated;
  ASSERT_TRUE(HeightMap::Create(extent, 0.01, &plain).ok());
  ASSERT_TRUE(HeightMap::Create(extent, 0.01, &corroborated).ok());
  for (size_t i = 0; i < points.size(); ++i) plain.Add(points[i], static_cast<int>(i));
  // Each point stands for the 2 mm grid's 4 mm^2: a quarter of a cell takes 7.
  corroborated.AddCorroborated(points, std::vector<float>(points.size(), 4e-6f), CellSupport());
  // The premise: the highest return per cell makes tips of them.
  EXPECT_GT(plain.ConvexTips(ConvexTipOptions()).size(), 3u);
  const std::vector<HeightMap::Tip> tips = corroborated.ConvexTips(ConvexTipOptions());
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_LT((tips[0].p.head<2>() - apex).norm(), 0.003);
  EXPECT_NEAR(tips[0].p.z(), 0.33, 0.004);
  EXPECT_TRUE(points[static_cast<size_t>(tips[0].source)].isApprox(tips[0].p, 1e-6));
}

TEST(HeightMap, ACellWithTooFewPointsStaysEmpty) {
  HeightMap map;
  ASSERT_TRUE(HeightMap::Create(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                                0.01, &map)
                  .ok());
  // Two points, 2 mm apart in height: corroborated by 2, not by 3.
  const std::vector<Eigen::Vector3d> points = {{0.505, 0.505, 1.0}, {0.506, 0.505, 0.998}};
  ConvexTipOptions loose;
  loose.min_neighbours = 0;
  CellSupport three;
  three.points = 3;
  map.AddCorroborated(points, {}, three);
  EXPECT_TRUE(map.ConvexTips(loose).empty());
  CellSupport two;
  two.points = 2;
  map.AddCorroborated(points, {}, two);
  const std::vector<HeightMap::Tip> tips = map.ConvexTips(loose);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_EQ(tips[0].source, 0);
  two.depth = 0.001;  // too shallow to reach the second point
  HeightMap shallow;
  ASSERT_TRUE(HeightMap::Create(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                                0.01, &shallow)
                  .ok());
  shallow.AddCorroborated(points, {}, two);
  EXPECT_TRUE(shallow.ConvexTips(loose).empty());
  CellSupport none;
  none.points = 0;
  EXPECT_FALSE(none.IsValid(nullptr));
}

// Each point stands for spacing^2 of surface: at a 2 mm spacing, a quarter
// of a 1 cm cell takes 7 points (4 do not), at 6 mm the 2 points.
TEST(HeightMap, TheCorroboratingPointsMustCoverAShareOfTheCell) {
  for (const auto& [spacing, count, kept] : {std::tuple<double, int, bool>{0.002, 4, false},
                                             {0.002, 7, true},
                                             {0.006, 1, false},
                                             {0.006, 2, true}}) {
    HeightMap map;
    ASSERT_TRUE(HeightMap::Create(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)),
                                  0.01, &map)
                    .ok());
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < count; ++k) points.emplace_back(0.501 + 0.001 * k, 0.505, 1.0 - 0.0005 * k);
    map.AddCorroborated(points, std::vector<float>(points.size(), spacing * spacing),
                        CellSupport());
    ConvexTipOptions loose;
    loose.min_neighbours = 0;
    EXPECT_EQ(map.ConvexTips(loose).size(), kept ? 1u : 0u) << spacing << " " << count;
  }
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
