// FindCoverings (solvers/refinement/coverings.h) on a virtual scan of the
// bundled robot wearing protective jackets over its upper arm and forearm,
// at the true pose, against the scanner's jacket labels: the jackets are
// found (recall) and little else is taken for them (precision). The CAD
// samples (4 mm, as the fit's) are sparser than the scan (3 mm) and each
// scanner sees a jacket from its own side, so most jacket cells are no
// sample's nearest over all scans. A sliding link is never covered.
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

struct JacketScene {
  KinematicModel model;
  std::vector<double> q;
  Pose T_world_base = PoseFromXyzRpy({0.2, -0.1, 0.0}, {0.0, 0.0, 2.7});
  VirtualScan scan;
  std::vector<SurfaceSamples> samples;
};

const JacketScene& GetJacketScene() {
  static const JacketScene* scene = [] {
    auto* out = new JacketScene;
    testing_util::LoadBundledRobotWithGun(
        "joint_1=0.7,joint_2=0.45,joint_3=0,joint_4=-0.5,joint_5=0.6,joint_6=0.6,gun_joint=0.09",
        &out->model, &out->q);
    AssetScanOptions options;
    CHECK(ApplySensorPreset("jackets", &options).ok());
    options.accessories = true;
    options.scan.spacing = 0.003;
    options.seed = 5;
    CHECK(ScanAsset(out->model, out->q, out->T_world_base, options, &out->scan, nullptr).ok());
    SamplingOptions sampling;
    sampling.spacing = 0.004;
    out->samples = SampleModelSurfaces(out->model, sampling);
    return out;
  }();
  return *scene;
}

TEST(CoveringsTest, FindsTheJacketsAtTheTruePose) {
  const JacketScene& scene = GetJacketScene();
  const VirtualScan& scan = scene.scan;
  CorrespondenceSearch search(&scan.scans, nullptr);
  CellMask covered;
  CoveringSummary summary;
  ASSERT_TRUE(FindCoverings(scene.model, scan.scans, &search, scene.samples, scene.T_world_base,
                            scene.q, CoveringOptions(), /*use_lattice=*/true, &covered, &summary)
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
  // Measured: recall 0.934, precision 0.869 (besides the jackets 7.3 k
  // cells of other accessories, coverings too, and 5.9 k link cells: 0.011
  // of the links'). Judging only the cells some sample took as its nearest
  // over all scans: recall 0.316; those spread over their blocks: 0.910.
  EXPECT_GT(recall, 0.8);
  EXPECT_GT(precision, 0.8);
  EXPECT_LT(links_lost, 0.03);
}

// At a jaw 50 mm short of the truth the electrode's far end lies off its
// CAD over an area, as a jacket would (878 of its cells were taken for a
// covering while sliding links could be covered).
TEST(CoveringsTest, NeverCoversASlidingLink) {
  const JacketScene& scene = GetJacketScene();
  std::vector<double> q = scene.q;
  const int electrode = scene.model.LinkIndex("gun_electrode");
  ASSERT_GE(electrode, 0);
  for (size_t j = 0; j < q.size(); ++j) {
    if (scene.model.joints()[j].name == "gun_joint") q[j] -= 0.05;
  }
  CorrespondenceSearch search(&scene.scan.scans, nullptr);
  CellMask covered;
  CoveringSummary summary;
  ASSERT_TRUE(FindCoverings(scene.model, scene.scan.scans, &search, scene.samples,
                            scene.T_world_base, q, CoveringOptions(), /*use_lattice=*/true,
                            &covered, &summary)
                  .ok());
  const size_t l = static_cast<size_t>(electrode);
  EXPECT_GT(summary.link_matched[l], 100u);
  EXPECT_EQ(summary.link_covered[l], 0u);
  EXPECT_TRUE(CoveringsHideALink(summary, CoveringOptions()));  // the jackets still do
}

}  // namespace
}  // namespace edgefit
