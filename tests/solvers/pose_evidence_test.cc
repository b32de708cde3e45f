// PoseEvidence: inliers speak for a pose, free space against it, hidden
// samples not at all.
#include "solvers/base/pose_evidence.h"

#include <gtest/gtest.h>

#include <vector>

namespace edgefit {
namespace {

TEST(PoseEvidenceTest, InliersLessFreeSpaceOverEverySample) {
  PoseEvidence evidence;
  // inlier 0.01, gate 0.04: two inliers, one between, one free, two hidden.
  evidence.Add({0.002f, 0.009f, 0.02f, 0.04f, -1.0f, -1.0f}, 0.01, 0.04);
  EXPECT_EQ(evidence.samples, 6u);
  EXPECT_EQ(evidence.inliers, 2);
  EXPECT_EQ(evidence.free_space, 1);
  EXPECT_DOUBLE_EQ(evidence.Share(), 1.0 / 6.0);
}

TEST(PoseEvidenceTest, HiddenSamplesSayNothingAndNoSamplesIsZero) {
  PoseEvidence none;
  EXPECT_EQ(none.Share(), 0.0);
  PoseEvidence hidden;
  hidden.Add(std::vector<float>(10, -1.0f), 0.01, 0.04);
  EXPECT_EQ(hidden.Share(), 0.0);
  // A pose seen in free space everywhere scores below a hidden one.
  PoseEvidence free;
  free.Add(std::vector<float>(10, 0.05f), 0.01, 0.04);
  EXPECT_LT(free.Share(), hidden.Share());
  EXPECT_DOUBLE_EQ(free.Share(), -1.0);
}

TEST(PoseEvidenceTest, AddsUpOverLinks) {
  PoseEvidence evidence;
  evidence.Add({0.001f, 0.001f}, 0.01, 0.04);
  evidence.Add({0.05f, -1.0f}, 0.01, 0.04);
  EXPECT_EQ(evidence.samples, 4u);
  EXPECT_DOUBLE_EQ(evidence.Share(), (2.0 - 1.0) / 4.0);
}

}  // namespace
}  // namespace edgefit
