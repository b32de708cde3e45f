// The base's verdict counts what hides it (QualityOptions::
// min_base_seen_share): a base whose samples facing the stations lie mostly
// behind scanned surfaces is not seen, however well its few samples in
// view match; a joint's body is judged on its samples in view alone.
#include <gtest/gtest.h>

#include <vector>

#include "model/bundled_robot_test_util.h"
#include "src/pipeline/stages.h"

namespace edgefit {
namespace {

WeightedIcpSummary Matching(size_t visible, size_t occluded) {
  WeightedIcpSummary summary;
  summary.visible_points = visible;
  summary.occluded_points = occluded;
  summary.inliers = visible;
  summary.inlier_share = 1.0;
  summary.rms = 0.001;
  return summary;
}

TEST(QualityTest, ABaseMostlyBehindScannedSurfacesIsNotSeen) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun("", &model, &q);
  const Body base = MakeBody(model, model.root_link(), -1);
  const SurfaceSamples samples;
  const QualityOptions options;
  // 27-37 % in view: right bases on virtual depth frames.
  EXPECT_EQ(Quality(model, base, samples, Matching(2700, 7300), options).verdict,
            JointVerdict::kOk);
  // 0.5-7 %: bases fitted onto clutter.
  const BodyQuality hidden = Quality(model, base, samples, Matching(649, 12382), options);
  EXPECT_EQ(hidden.verdict, JointVerdict::kNotSeen);
  EXPECT_FALSE(hidden.ok);
  EXPECT_NEAR(hidden.SeenShare(), 0.05, 0.001);
  // Nothing faces a station in its window: nothing hides it either.
  EXPECT_EQ(Quality(model, base, samples, Matching(0, 0), options).SeenShare(), 1.0);
  // A joint's body is judged on what is in view.
  const int joint = model.JointIndex("joint_2");
  const Body link = MakeBody(model, model.joints()[static_cast<size_t>(joint)].child_link, joint);
  EXPECT_EQ(Quality(model, link, samples, Matching(649, 12382), options).verdict,
            JointVerdict::kOk);
}

}  // namespace
}  // namespace edgefit
