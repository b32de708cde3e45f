// The symmetry axis of arm tips (paper Sec. 6.1, Fig. 11b): recovered from
// mirrored tips among unpaired ones, refined by least squares; parallel
// shifted pairs give distinct axes; same input, same axes.
#include "solvers/base/symmetry_axis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "edgefit/core/angles.h"
#include "edgefit/core/split_mix64.h"

namespace edgefit {
namespace {

// Tips mirrored about the line through `point` along `yaw`, at distances
// `half_widths` either side and positions `along` on it, with noise.
std::vector<Eigen::Vector3d> MirroredTips(const Eigen::Vector2d& point, double yaw,
                                          const std::vector<double>& along,
                                          const std::vector<double>& half_widths, double noise,
                                          uint64_t seed) {
  const Eigen::Vector2d d(std::cos(yaw), std::sin(yaw)), n(-d.y(), d.x());
  SplitMix64 random(seed);
  std::vector<Eigen::Vector3d> tips;
  for (size_t k = 0; k < along.size(); ++k) {
    for (const double side : {-1.0, 1.0}) {
      const Eigen::Vector2d p = point + along[k] * d + side * half_widths[k] * n;
      tips.emplace_back(p.x() + random.Uniform(-noise, noise),
                        p.y() + random.Uniform(-noise, noise), 1.7 + 0.1 * static_cast<double>(k));
    }
  }
  return tips;
}

TEST(SymmetryAxis, RecoversTheAxisAmongUnpairedTips) {
  const Eigen::Vector2d point(2.0, -1.0);
  const double yaw = 30.0 * kDeg;
  std::vector<Eigen::Vector3d> tips =
      MirroredTips(point, yaw, {-1.4, 0.2, 1.5}, {0.45, 0.5, 0.4}, 0.002, 1);
  // Unpaired: box corners, clutter.
  tips.emplace_back(0.3, 0.8, 1.2);
  tips.emplace_back(3.1, 0.4, 0.9);
  tips.emplace_back(-0.5, -2.0, 1.7);
  const std::vector<SymmetryAxis> axes = FindSymmetryAxes(tips, SymmetryAxisOptions());
  ASSERT_FALSE(axes.empty());
  const SymmetryAxis& axis = axes.front();
  ASSERT_EQ(axis.pairs.size(), 3u);
  EXPECT_LT(std::acos(std::abs(axis.direction.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw))))),
            0.3 * kDeg);
  const Eigen::Vector2d normal(-std::sin(yaw), std::cos(yaw));
  EXPECT_LT(std::abs(normal.dot(axis.point - point)), 0.002);
  EXPECT_LT(axis.rms, 0.004);
  for (const auto& [a, b] : axis.pairs) EXPECT_EQ(a / 2, b / 2);  // the mirrored ones
  // Same tips, same answer.
  const std::vector<SymmetryAxis> again = FindSymmetryAxes(tips, SymmetryAxisOptions());
  EXPECT_EQ(again.front().point, axis.point);
  EXPECT_EQ(again.front().direction, axis.direction);
}

TEST(SymmetryAxis, ShiftedParallelPairsGiveDistinctAxes) {
  // A pair about y = 0 and one about y = 0.05 (clamps opened unequally),
  // heights apart so that neither tip pairs across.
  std::vector<Eigen::Vector3d> tips = MirroredTips({0, 0}, 0.0, {-1.0}, {0.45}, 0.0, 1);
  for (const Eigen::Vector3d& t : MirroredTips({0, 0.05}, 0.0, {1.0}, {0.5}, 0.0, 1)) {
    tips.push_back(t + Eigen::Vector3d(0, 0, 0.1));
  }
  const std::vector<SymmetryAxis> axes = FindSymmetryAxes(tips, SymmetryAxisOptions());
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[0].pairs.size(), 1u);
  EXPECT_EQ(axes[1].pairs.size(), 1u);
  EXPECT_NEAR(std::abs(axes[0].point.y() - axes[1].point.y()), 0.05, 1e-9);
}

TEST(SymmetryAxis, DrawnHypothesesWhenThereAreManyTips) {
  std::vector<Eigen::Vector3d> tips =
      MirroredTips({0, 0}, 10.0 * kDeg, {-1.0, 0.0, 1.0}, {0.4, 0.45, 0.5}, 0.001, 2);
  SplitMix64 random(3);
  for (int k = 0; k < 60; ++k) {  // clutter, some at the pairs' heights
    tips.emplace_back(random.Uniform(-3, 3), random.Uniform(-3, 3),
                      k % 3 == 0 ? 1.7 : random.Uniform(0.5, 2.5));
  }
  SymmetryAxisOptions options;
  options.iterations = 20;  // fewer than the admissible pairs (equal heights): drawn
  options.seed = 4;
  const std::vector<SymmetryAxis> axes = FindSymmetryAxes(tips, options);
  ASSERT_FALSE(axes.empty());
  EXPECT_GE(axes.front().pairs.size(), 3u);
  EXPECT_LT(std::acos(std::abs(axes.front().direction.dot(
                Eigen::Vector2d(std::cos(10.0 * kDeg), std::sin(10.0 * kDeg))))),
            0.3 * kDeg);
}

TEST(SymmetryAxis, NoPairNoAxis) {
  EXPECT_TRUE(FindSymmetryAxes({}, SymmetryAxisOptions()).empty());
  EXPECT_TRUE(FindSymmetryAxes({{0, 0, 1}, {1, 0, 2}}, SymmetryAxisOptions()).empty());
  SymmetryAxisOptions bad;
  bad.tolerance = 0.0;
  EXPECT_FALSE(bad.IsValid(nullptr));
}

}  // namespace
}  // namespace edgefit
