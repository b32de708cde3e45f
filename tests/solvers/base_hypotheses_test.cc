// Ranking the base's rough poses (solvers/base/base_hypotheses.h) with a
// synthetic loss: the best first, distinct runners-up within the margin
// kept, an elongated base slid along its length to the loss's minimum.
#include "solvers/base/base_hypotheses.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "edgefit/core/angles.h"

namespace edgefit {
namespace {

void Quiet(const std::string&) {}

TEST(BaseHypothesesTest, DistinctByFiveDegreesOrFiveCentimetres) {
  const Pose a = PoseFromXyYaw(1.0, 2.0, 0.3);
  EXPECT_FALSE(IsDistinctPose(a, PoseFromXyYaw(1.03, 2.0, 0.3 + 4.0 * kDeg)));
  EXPECT_TRUE(IsDistinctPose(a, PoseFromXyYaw(1.06, 2.0, 0.3)));
  EXPECT_TRUE(IsDistinctPose(a, PoseFromXyYaw(1.0, 2.0, 0.3 + 6.0 * kDeg)));
}

TEST(BaseHypothesesTest, BestFirstThenDistinctRunnersUpWithinTheMargin) {
  // Loss per sample: the distance of the pose's x from 0 [m].
  const size_t samples = 100;
  const BasePoseLoss loss = [&](const Pose& T) {
    return static_cast<double>(samples) * std::abs(T.translation().x());
  };
  std::vector<Pose> candidates = {PoseFromXyYaw(0.5, 0.0, 0.0), PoseFromXyYaw(0.0005, 0.0, M_PI),
                                  PoseFromXyYaw(0.0, 0.0, 0.0), PoseFromXyYaw(0.01, 0.0, 0.0)};
  BaseHypothesesOptions options;
  options.alternatives = 0;
  std::vector<Pose> roughs = RankBaseHypotheses(&candidates, Eigen::Vector3d(1, 1, 1), true, loss,
                                                samples, options, &Quiet);
  ASSERT_EQ(roughs.size(), 1u);  // the best alone
  EXPECT_NEAR(roughs[0].translation().x(), 0.0, 1e-12);
  options.alternatives = 2;
  roughs = RankBaseHypotheses(&candidates, Eigen::Vector3d(1, 1, 1), true, loss, samples, options,
                              &Quiet);
  // The half-turned pose 0.5 mm/sample worse is kept; x = 0.01 is not
  // distinct from the best; x = 0.5 is beyond the 1 mm/sample margin.
  ASSERT_EQ(roughs.size(), 2u);
  EXPECT_NEAR(roughs[1].translation().x(), 0.0005, 1e-12);
}

TEST(BaseHypothesesTest, AnElongatedBaseSlidesAlongItsLength) {
  // A 4 m long, 0.5 m wide base turned 90 degrees: its length runs along
  // world y; the loss is lowest at y = 1.234.
  const BasePoseLoss loss = [](const Pose& T) { return std::abs(T.translation().y() - 1.234); };
  std::vector<Pose> candidates = {PoseFromXyYaw(0.2, 0.0, M_PI / 2)};
  const std::vector<Pose> roughs = RankBaseHypotheses(
      &candidates, Eigen::Vector3d(4.0, 0.5, 0.3), true, loss, 1, BaseHypothesesOptions(), &Quiet);
  ASSERT_EQ(roughs.size(), 1u);
  EXPECT_NEAR(roughs[0].translation().y(), 1.234, 0.011);  // the fine step: 1 cm
  EXPECT_NEAR(roughs[0].translation().x(), 0.2, 1e-12);
  EXPECT_NEAR(candidates[0].translation().y(), roughs[0].translation().y(), 1e-12);
  // Not elongated, or not asked to: left where it was.
  candidates = {PoseFromXyYaw(0.2, 0.0, M_PI / 2)};
  EXPECT_NEAR(RankBaseHypotheses(&candidates, Eigen::Vector3d(1.0, 0.5, 0.3), true, loss, 1,
                                 BaseHypothesesOptions(), &Quiet)[0]
                  .translation()
                  .y(),
              0.0, 1e-12);
}

TEST(BaseHypothesesTest, OptionsAreChecked) {
  BaseHypothesesOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.instance_separation = 0.5;  // the cell fit's
  EXPECT_TRUE(options.IsValid(&error)) << error;
  options.instance_separation = 0.0;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("instance_separation"), std::string::npos) << error;
}

}  // namespace
}  // namespace edgefit
