#include "edgefit/scanner/edge_metrics.h"

#include <gtest/gtest.h>

#include "edgefit/scene/scene.h"

namespace edgefit {
namespace {

TEST(EdgeMetricsTest, CountsPerClass) {
  const uint16_t link = LinkLabel(0), edge = LinkLabel(1) | kTrueEdgeFlag;
  // scan 0: 2 true edges (1 found), 2 plain link points (1 wrongly high),
  // an accessory point found high, a background point, a missing cell.
  // scan 1: one more true edge found, one accessory not high.
  const std::vector<std::vector<uint16_t>> labels = {
      {edge, edge, link, link, kLabelAccessory, kLabelBackground, kLabelMissing},
      {edge, kLabelAccessory}};
  const std::vector<std::vector<float>> w = {{10, 1, 10, 1, 10, 1, 0}, {10, 1}};
  const EdgeMetrics m = EvaluateEdgeWeights(labels, w);
  EXPECT_EQ(m.link_points, 5u);
  EXPECT_EQ(m.true_edges, 3u);
  EXPECT_EQ(m.link_high, 3u);
  EXPECT_EQ(m.true_positives, 2u);
  EXPECT_DOUBLE_EQ(m.precision(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.recall(), 2.0 / 3.0);
  EXPECT_EQ(m.accessory_points, 2u);
  EXPECT_DOUBLE_EQ(m.accessory_share(), 0.5);
  EXPECT_DOUBLE_EQ(m.accessory_share_of_high(), 0.25);
  EXPECT_EQ(m.background_points, 1u);
  EXPECT_EQ(m.background_high, 0u);
  EXPECT_NE(m.BriefReport().find("precision 0.667"), std::string::npos);
}

TEST(EdgeMetricsTest, EmptyIsZeroNotNan) {
  const EdgeMetrics m = EvaluateEdgeWeights({}, {});
  EXPECT_EQ(m.precision(), 0.0);
  EXPECT_EQ(m.recall(), 0.0);
  EXPECT_EQ(m.accessory_share(), 0.0);
}

}  // namespace
}  // namespace edgefit
