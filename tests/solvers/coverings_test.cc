// FindCoverings (solvers/refinement/coverings.h) on a virtual scan of the
// bundled robot wearing protective jackets over its upper arm and forearm,
// at the true pose, against the scanner's jacket labels: the jackets are
// found (recall) and little else is taken for them (precision). The CAD
// samples (4 mm, as the fit's) are sparser than the scan (3 mm) and each
// scanner sees a jacket from its own side, so most jacket cells are no
// sample's nearest over all scans.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "edgefit/model/surface_sampler.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scene/scene.h"
#include "model/bundled_robot_test_util.h"
#include "solvers/refinement/coverings.h"

namespace edgefit {
namespace {

TEST(CoveringsTest, FindsTheJacketsAtTheTruePose) {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun(
      "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
      &model, &q);
  const Pose T_world_base = PoseFromXyzRpy({0.2, -0.1, 0.0}, {0.0, 0.0, 2.7});
  AssetScanOptions options;
  ASSERT_TRUE(ApplySensorPreset("jackets", &options).ok());
  options.accessories = true;
  options.scan.spacing = 0.003;
  options.seed = 5;
  VirtualScan scan;
  ASSERT_TRUE(ScanAsset(model, q, T_world_base, options, &scan, nullptr).ok());

  SamplingOptions sampling;
  sampling.spacing = 0.004;
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
  CorrespondenceSearch search(&scan.scans, nullptr);
  CellMask covered;
  CoveringSummary summary;
  ASSERT_TRUE(FindCoverings(model, scan.scans, &search, samples, T_world_base, q,
                            CoveringOptions(), /*use_lattice=*/true, &covered, &summary)
                  .ok());

  size_t jacket = 0, found = 0, taken = 0, link_taken = 0, link_cells = 0, accessory_taken = 0;
  for (size_t s = 0; s < scan.scans.scans.size(); ++s) {
    for (size_t i = 0; i < covered[s].size(); ++i) {
      const uint16_t label = scan.labels[s][i];
      const bool is_jacket = (label & kJacketFlag) != 0;
      const bool is_link = (label & kLabelMask) >= kLabelFirstLink;
      jacket += is_jacket;
      found += is_jacket && covered[s][i];
      taken += covered[s][i];
      link_cells += is_link;
      link_taken += is_link && covered[s][i];
      accessory_taken += !is_jacket && (label & kLabelMask) == kLabelAccessory && covered[s][i];
    }
  }
  ASSERT_GT(jacket, 10000u);
  const double recall = static_cast<double>(found) / jacket;
  const double precision = static_cast<double>(found) / taken;
  const double links_lost = static_cast<double>(link_taken) / link_cells;
  std::printf(
      "  %zu jacket cells: recall %.3f, precision %.3f; %.3f of the link cells taken; %zu other "
      "accessory cells, %zu link cells\n",
      jacket, recall, precision, links_lost, accessory_taken, link_taken);
  // Measured: recall 0.934, precision 0.868 (besides the jackets 7.3 k
  // cells of other accessories, coverings too, and 6.1 k link cells: 0.012
  // of the links'). Judging only the cells some sample took as its nearest
  // over all scans: recall 0.316; those spread over their blocks: 0.910.
  EXPECT_GT(recall, 0.8);
  EXPECT_GT(precision, 0.8);
  EXPECT_LT(links_lost, 0.03);
}

}  // namespace
}  // namespace edgefit
