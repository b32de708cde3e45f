// DetectEdges end to end on virtual scans with true-edge flags.
#include "edgefit/edges/edge_detector.h"

#include <gtest/gtest.h>
#include <omp.h>

#include "edgefit/scanner/edge_metrics.h"
#include "edges/edges_test_util.h"

namespace edgefit {
namespace {

// A box on a floor, 3 scanners, 1 mm noise, 1.7 mm spacing. The truth flags
// mark points within 1.5 mm of an edge; the detector's band is wider (S
// stays below tau_dot up to ~5 mm from an edge, Eq. 3 with r_max = 10 mm)
// and silhouette edges (one face visible) cannot be detected from one scan,
// so strict precision is low. Measured (tau_dot 0.8): strict precision
// 0.20, recall 0.55; 71% of the flagged points lie within 5 mm of an edge.
TEST(EdgeDetectorTest, BoxEdgesAgainstTruth) {
  const VirtualScan scan = edges_test::ScanBox(0.001, 3);
  EdgeDetectionOptions options;
  options.tau_dot = 0.8;
  EdgeDetectionResult result;
  ASSERT_TRUE(DetectEdges(scan.scans, options, &result).ok());
  const EdgeMetrics strict = EvaluateEdgeWeights(scan.labels, result.w_edge);
  size_t flagged = 0, within_5mm = 0;
  for (size_t s = 0; s < scan.labels.size(); ++s) {
    for (size_t i = 0; i < scan.labels[s].size(); ++i) {
      if (!IsLinkLabel(scan.labels[s][i]) || !(result.w_edge[s][i] > 1.0f)) continue;
      Eigen::Vector3d face;
      ++flagged;
      if (edges_test::BoxEdgeDistance(scan.scans.scans[s].PointWorld(i), &face) < 0.005) {
        ++within_5mm;
      }
    }
  }
  const double precision_5mm = static_cast<double>(within_5mm) / std::max<size_t>(1, flagged);
  std::printf("%s\nregions %zu candidates %zu edge points %zu; precision within 5 mm %.3f\n",
              strict.BriefReport().c_str(), result.regions, result.candidates, result.edge_points,
              precision_5mm);
  EXPECT_GT(strict.recall(), 0.5);
  EXPECT_GT(precision_5mm, 0.6);
  EXPECT_GT(strict.precision(), 0.15);
  EXPECT_GE(result.regions, 2u);
  // Eq. (6): w is w_high, 1 or 0 (missing).
  for (size_t s = 0; s < result.w_edge.size(); ++s) {
    for (size_t i = 0; i < result.w_edge[s].size(); ++i) {
      const float w = result.w_edge[s][i];
      EXPECT_TRUE(scan.scans.scans[s].IsValid(i) ? (w == 1.0f || w == 10.0f) : w == 0.0f);
    }
  }
}

// A long vertical cylinder (no rim in view, 256 segments: 1.4 degree facets)
// has no sharp edges: no valid regions.
TEST(EdgeDetectorTest, SmoothCylinderHasNoRegions) {
  Scene scene;
  scene.meshes.push_back(
      edges_test::LinkMesh(MakeCylinderMesh(0.3, 10.0, 256), Pose::Identity(), 0));
  VirtualScanOptions options;
  options.window_margin_deg = 0.0;
  options.asset_box_world = Eigen::AlignedBox3d(Eigen::Vector3d(-0.3, -0.3, -0.3),
                                                Eigen::Vector3d(0.3, 0.3, 0.3));
  const std::vector<Pose> poses = {Pose(Eigen::Translation3d(-2.5, 0, 0)),
                                   PoseFromXyYaw(2.0, 1.0, M_PI + std::atan2(1.0, 2.0))};
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, poses, options, &scan).ok());
  EdgeDetectionResult result;
  ASSERT_TRUE(DetectEdges(scan.scans, EdgeDetectionOptions(), &result).ok());
  std::printf("cylinder: points %zu candidates %zu regions %zu\n", result.points,
              result.candidates, result.regions);
  EXPECT_GT(result.points, 100000u);
  EXPECT_EQ(result.regions, 0u);
  EXPECT_EQ(result.edge_points, 0u);
}

TEST(EdgeDetectorTest, InvalidOptionsFail) {
  const auto fails = [](auto mutate) {
    EdgeDetectionOptions options;
    mutate(&options);
    std::string error;
    EXPECT_FALSE(options.IsValid(&error));
    EXPECT_FALSE(error.empty());
    EdgeDetectionResult result;
    const Status status = DetectEdges(ScanSet(), options, &result);
    EXPECT_FALSE(status.ok());
  };
  fails([](EdgeDetectionOptions* o) { o->normal_radius = 0; });
  fails([](EdgeDetectionOptions* o) { o->max_half_window = 0; });
  fails([](EdgeDetectionOptions* o) { o->tau_align = 1.5; });
  fails([](EdgeDetectionOptions* o) { o->r_max = o->r_min; });
  fails([](EdgeDetectionOptions* o) { o->tau_dot = 0; });
  fails([](EdgeDetectionOptions* o) { o->region_radius = -1; });
  fails([](EdgeDetectionOptions* o) { o->tau_region = std::nan(""); });
  fails([](EdgeDetectionOptions* o) { o->tau_min = 0; });
  fails([](EdgeDetectionOptions* o) { o->w_high = 0.5; });
  std::string error;
  EXPECT_TRUE(EdgeDetectionOptions().IsValid(&error)) << error;
}

TEST(EdgeDetectorTest, UnorganizedOrLatticeLessScansFail) {
  ScanSet scans;
  scans.scans.emplace_back(1, 10);
  scans.scans.back().set_organized(false);
  EdgeDetectionResult result;
  Status status = DetectEdges(scans, EdgeDetectionOptions(), &result);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("organized"), std::string::npos) << status.message();
  scans.scans.back().set_organized(true);  // still no lattice
  status = DetectEdges(scans, EdgeDetectionOptions(), &result);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("lattice"), std::string::npos) << status.message();
}

TEST(EdgeDetectorTest, SameResultForOneAndTwoThreads) {
  const VirtualScan scan = edges_test::ScanBox(0.001, 2, 7);
  EdgeDetectionOptions options;
  options.tau_dot = 0.8;
  const int saved = omp_get_max_threads();
  EdgeDetectionResult one, two;
  omp_set_num_threads(1);
  ASSERT_TRUE(DetectEdges(scan.scans, options, &one).ok());
  omp_set_num_threads(2);
  ASSERT_TRUE(DetectEdges(scan.scans, options, &two).ok());
  omp_set_num_threads(saved);
  EXPECT_GT(one.edge_points, 0u);
  EXPECT_EQ(one.w_edge, two.w_edge);
  EXPECT_EQ(one.candidates, two.candidates);
  EXPECT_EQ(one.regions, two.regions);
  ASSERT_EQ(one.scores.size(), two.scores.size());
  for (size_t s = 0; s < one.scores.size(); ++s) {
    EXPECT_EQ(0, std::memcmp(one.scores[s].data(), two.scores[s].data(),
                             one.scores[s].size() * sizeof(float)));
    EXPECT_EQ(0, std::memcmp(one.normals[s].data(), two.normals[s].data(),
                             one.normals[s].size() * sizeof(Eigen::Vector3f)));
  }
}

}  // namespace
}  // namespace edgefit
