// Structured outliers: a link with a cable tube
// lying on it, scanned by the virtual scanner (3 scanners, 1.7 mm spacing,
// 1 mm noise). The tube is not in the CAD model and makes about 30 % of the
// points near the link. With the paper's fixed gate, edge-weighted ICP
// (Eq. (8) with the Eq. (6) weights of the real edge detector) holds the
// rotation that uniform weights lose to the tube; with the engine's
// shrinking gate and visibility test the tube drops out for both.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "correspondence/correspondence_test_util.h"
#include "edgefit/core/angles.h"
#include "edgefit/edges/edge_detector.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/scene.h"
#include "edgefit/scene/tube_mesh.h"
#include "solvers/icp_test_util.h"
#include "solvers/link_scan_test_util.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {
namespace {

using testing_util::LinkMesh;
using testing_util::RotationErrorRad;
using testing_util::TranslationError;

constexpr double kTubeRadius = 0.028;  // [m]

// The link held 1.1 m above the floor, as a robot's forearm would be.
const Pose kTrueLinkPose = PoseFromXyzRpy({0.3, -0.2, 1.1}, {0.1, -0.05, 0.6});

struct TubeScene {
  ScanSet scans;
  EdgeDetectionResult edges;
  SurfaceSamples samples;      // link frame
  double outlier_share = 0.0;  // tube points / (tube + link points)
};

const TubeScene& GetTubeScene() {
  static TubeScene* scene = [] {
    auto* out = new TubeScene;
    // The cable (link frame): along the top of the long box, then up the
    // inner face of the upright one, both ends hanging free.
    const double r = kTubeRadius;
    const std::vector<Eigen::Vector3d> control = {
        {-0.16, 0.02, 0.02 + r},    {-0.08, 0.02, 0.05 + r}, {0.08, 0.03, 0.05 + r},
        {0.20 - r, 0.03, 0.08 + r}, {0.20 - r, 0.02, 0.28},  {0.14, 0.02, 0.46},
        {0.02, 0.0, 0.50}};
    SceneMesh tube;
    tube.mesh_world.Append(MakeTubeMesh(CatmullRomCurve(control, 0.005), r, 24), kTrueLinkPose);
    tube.label = kLabelAccessory;
    tube.kind = "harness";

    VirtualScan scan =  // 1.7 mm, 1 mm noise
        testing_util::ScanLinkOnFloor(LinkMesh(), kTrueLinkPose, {tube}, 3);
    size_t link_points = 0, tube_points = 0;
    for (const std::vector<uint16_t>& labels : scan.labels) {
      for (const uint16_t label : labels) {
        link_points += IsLinkLabel(label);
        tube_points += (label & kLabelMask) == kLabelAccessory;
      }
    }
    out->outlier_share =
        static_cast<double>(tube_points) / static_cast<double>(tube_points + link_points);
    out->scans = std::move(scan.scans);
    CHECK(DetectEdges(out->scans, EdgeDetectionOptions(), &out->edges).ok());
    out->samples = SampleMeshSurface(LinkMesh(), 0.004, 9);
    return out;
  }();
  return *scene;
}

struct Errors {
  double translation = 0.0;  // [m]
  double rotation = 0.0;     // [rad]
};

// Fits the link from 4 mm / 1.5 degrees off. fixed_gate: the paper's
// weighted ICP, every match within 3 cm counts in every iteration; else
// the engine's default gate schedule (3 cm halving to 5 mm).
Errors FitLink(bool uniform_weights, bool fixed_gate) {
  const TubeScene& s = GetTubeScene();
  // Uniform weights: a search without weights.
  CorrespondenceSearch search(&s.scans, uniform_weights ? nullptr : &s.edges.w_edge);
  WeightedIcp icp(&s.scans, &search);
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.03;
  if (fixed_gate) options.final_gate = options.correspondence.max_distance;
  options.max_iterations = 200;
  LinkState state;
  state.T_world_link = kTrueLinkPose * PoseFromXyzRpy({0.004, -0.003, 0.003}, {0.01, -0.015, 0.02});
  WeightedIcpSummary summary;
  const Status status = icp.Fit(s.samples, LinkMotion::Free(), options, &state, &summary);
  EXPECT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(summary.stop_reason, IcpStopReason::kConverged);
  Errors e{TranslationError(state.T_world_link, kTrueLinkPose),
           RotationErrorRad(state.T_world_link, kTrueLinkPose)};
  std::printf("  %s gate, %s weights: %s; error %.3f mm, %.4f deg\n",
              fixed_gate ? "fixed" : "shrinking", uniform_weights ? "uniform" : "edge",
              summary.BriefReport().c_str(), e.translation * 1e3, e.rotation / kDeg);
  return e;
}

TEST(TubeOutlierTest, TubeIsAboutThirtyPercentAndNotEdges) {
  const TubeScene& s = GetTubeScene();
  std::printf("  tube share of link + tube points: %.3f; %zu edge points of %zu\n", s.outlier_share,
              s.edges.edge_points, s.edges.points);
  EXPECT_GT(s.outlier_share, 0.25);
  EXPECT_LT(s.outlier_share, 0.40);
}

// The paper's weighted ICP (every match within the 3 cm gate counts): the
// tube pulls the uniform fit off by about 0.27 degrees; edge weights, which
// the tube does not get, cut the rotation error by more than half.
// (Measured: edge 0.095 deg, 0.90 mm; uniform 0.274 deg, 0.83 mm: neither
// recovers the translation with the tube's matches in the data term.)
TEST(TubeOutlierTest, FixedGateEdgeWeightsBeatUniformWeights) {
  const Errors edge = FitLink(false, true);
  const Errors uniform = FitLink(true, true);
  EXPECT_LT(edge.rotation, 0.12 * kDeg);
  EXPECT_GT(uniform.rotation, 0.2 * kDeg);
  EXPECT_LT(edge.rotation, 0.5 * uniform.rotation);
}

// The engine's defaults (gate halving to 5 mm, seen samples only) drop the
// tube's matches once the estimate is close: both weightings recover the
// pose. (Measured: edge 0.18 mm, 0.016 deg; uniform 0.09 mm, 0.009 deg:
// at a tight gate the edge band's fewer matches weigh most and cost
// accuracy; BENCHMARK.md's w_high ablation measures the same question on
// whole robots.)
TEST(TubeOutlierTest, ShrinkingGateRecoversThePoseWithEitherWeighting) {
  for (const bool uniform : {false, true}) {
    const Errors e = FitLink(uniform, false);
    EXPECT_LT(e.translation, 0.0004);
    EXPECT_LT(e.rotation, 0.05 * kDeg);
  }
}

}  // namespace
}  // namespace edgefit
