// Sec. 4.3 region growing on hand-made candidates.
#include "edgefit/edges/region_growing.h"

#include <gtest/gtest.h>

namespace edgefit {
namespace {

// A straight strip of `count` candidates 1 mm apart along x starting at
// `origin`, all with normal `n`.
void AddStrip(const Eigen::Vector3f& origin, int count, const Eigen::Vector3f& n, float score,
              EdgeCandidates* candidates) {
  for (int k = 0; k < count; ++k) {
    candidates->Add(origin + Eigen::Vector3f(0.001f * k, 0, 0), n, score);
  }
}

TEST(RegionGrowingTest, KeepsLongStripDropsSmallNoiseRegions) {
  EdgeCandidates candidates;
  AddStrip({0, 0, 0}, 400, {0, 0, 1}, 0.5f, &candidates);   // a structural edge
  AddStrip({0, 1, 0}, 50, {0, 0, 1}, 0.3f, &candidates);    // noise blob, lower scores
  AddStrip({0, 2, 0}, 299, {0, 1, 0}, 0.6f, &candidates);   // one short of tau_min
  RegionGrowingOptions options;  // tau_min 300
  RegionGrowingResult result;
  GrowEdgeRegions(candidates, options, &result);
  EXPECT_EQ(result.regions, 1u);
  EXPECT_EQ(result.edge_points, 400u);
  for (int k = 0; k < 400; ++k) EXPECT_EQ(result.region[k], 0);
  for (size_t k = 400; k < candidates.size(); ++k) EXPECT_EQ(result.region[k], -1);
}

// Eq. (5): two touching strips whose normals differ by 90 degrees stay two
// regions; a normal flip (n vs -n) does not split (absolute dot product).
TEST(RegionGrowingTest, NormalConsistencySplitsRegions) {
  EdgeCandidates candidates;
  AddStrip({0, 0, 0}, 320, {0, 0, 1}, 0.5f, &candidates);
  AddStrip({0, 0.002f, 0}, 320, {0, 1, 0}, 0.5f, &candidates);
  AddStrip({0, 0.004f, 0}, 320, {0, -1, 0}, 0.5f, &candidates);
  RegionGrowingOptions options;
  RegionGrowingResult result;
  GrowEdgeRegions(candidates, options, &result);
  EXPECT_EQ(result.regions, 2u);
  EXPECT_NE(result.region[0], result.region[320]);
  EXPECT_EQ(result.region[320], result.region[640]);
}

TEST(RegionGrowingTest, EmptyInput) {
  RegionGrowingResult result;
  GrowEdgeRegions(EdgeCandidates(), RegionGrowingOptions(), &result);
  EXPECT_EQ(result.regions, 0u);
  EXPECT_TRUE(result.region.empty());
}

}  // namespace
}  // namespace edgefit
