// The 2D hash grid's radius queries against brute force: points on lines
// and clusters (a section's shape), queries near them, on the box's border,
// far outside it and at negative coordinates; radii below, at and above a
// cell (the last without the occupancy bits' shortcut).
#include "solvers/base/point_grid2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace edgefit {
namespace {

bool BruteAnyWithin(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& p,
                    double radius) {
  for (const Eigen::Vector2d& q : points) {
    if ((q - p).squaredNorm() <= radius * radius) return true;
  }
  return false;
}

TEST(PointGrid2, AnyWithinIsBruteForceEverywhere) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 400; ++i) {  // a line across the origin, and a cluster
    points.emplace_back(-1.3 + 0.005 * i, 0.2 - 0.002 * i);
    points.emplace_back(0.7 + 0.05 * unit(rng), -0.4 + 0.05 * unit(rng));
  }
  const double cell = 0.01;
  const PointGrid2 grid(points, cell);
  int hits = 0, queries = 0;
  for (const double radius : {0.004, cell, 0.025}) {
    for (int i = 0; i < 20000; ++i) {
      Eigen::Vector2d p;
      if (i % 4 == 0) {  // anywhere, far outside the box too
        p = Eigen::Vector2d(-4.0 + 8.0 * unit(rng), -4.0 + 8.0 * unit(rng));
      } else {  // near a point
        p = points[static_cast<size_t>(rng() % points.size())] +
            Eigen::Vector2d(0.06 * unit(rng) - 0.03, 0.06 * unit(rng) - 0.03);
      }
      const bool expected = BruteAnyWithin(points, p, radius);
      ASSERT_EQ(grid.AnyWithin(p, radius), expected) << p.transpose() << " r " << radius;
      hits += expected;
      ++queries;
    }
  }
  // Both answers were asked for often.
  EXPECT_GT(hits, queries / 10);
  EXPECT_LT(hits, queries * 9 / 10);
}

TEST(PointGrid2, NoPointsHasNoNeighbours) {
  const std::vector<Eigen::Vector2d> none;
  const PointGrid2 grid(none, 0.01);
  EXPECT_FALSE(grid.AnyWithin(Eigen::Vector2d(0.0, 0.0), 0.01));
}

}  // namespace
}  // namespace edgefit
