// Scans of posed URDF models on a floor: every link-labelled point lies on
// its link's posed mesh within the range noise, background points on the floor.
#include <gtest/gtest.h>

#include <filesystem>

#include "edgefit/scanner/random_joints.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/model_scene.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

// Fraction of link points within 3 sigma of their labelled link's posed mesh
// and of background points within 3 sigma of the floor (z = 0). The distance
// to the surface is at most the along-ray noise, so >= 99.73% are expected.
void CheckPointsOnTheirMeshes(const KinematicModel& model, const std::vector<double>& q,
                              const Pose& T_world_base, double spacing, int scanners,
                              size_t min_link_points) {
  Scene scene;
  scene.meshes.push_back(testing_util::FloorMesh());
  AddModelToScene(model, model.ForwardKinematics(q, T_world_base), &scene);
  ScannerPlacementOptions placement;
  placement.count = scanners;
  placement.seed = 5;
  const std::vector<Pose> poses = PlaceScanners(model.BoundingBox(q, T_world_base), placement);
  VirtualScanOptions options;
  options.spacing = spacing;
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, poses, options, &scan).ok());
  ASSERT_EQ(scan.scans.scans.size(), poses.size());

  const double three_sigma = 3.0 * options.noise_sigma;
  std::vector<std::unique_ptr<testing_util::MeshProximity>> near_link(model.links().size());
  for (const SceneMesh& m : scene.meshes) {
    if (m.link >= 0) {
      near_link[m.link] = std::make_unique<testing_util::MeshProximity>(m.mesh_world, three_sigma);
    }
  }
  size_t link = 0, link_near = 0, background = 0, background_near = 0, far_background = 0;
  for (size_t k = 0; k < scan.scans.scans.size(); ++k) {
    const OrganizedScan& s = scan.scans.scans[k];
    for (size_t i = 0; i < s.size(); ++i) {
      const uint16_t label = scan.labels[k][i];
      if (label == kLabelMissing) continue;
      const Eigen::Vector3d p = s.PointWorld(i);
      if (IsLinkLabel(label)) {
        const int l = LinkOfLabel(label);
        ASSERT_TRUE(l >= 0 && static_cast<size_t>(l) < near_link.size() && near_link[l]);
        ++link;
        link_near += near_link[l]->Within(p);
      } else {
        ASSERT_EQ(label, kLabelBackground);
        ++background;
        background_near += std::abs(p.z()) <= three_sigma;
        far_background += std::abs(p.z()) > 2.0 * three_sigma;
      }
    }
  }
  EXPECT_GE(link, min_link_points);
  EXPECT_GT(background, 1000u);
  EXPECT_GE(static_cast<double>(link_near), 0.997 * link) << link_near << " of " << link;
  EXPECT_GE(static_cast<double>(background_near), 0.997 * background);
  EXPECT_LT(far_background, background / 10000 + 1);
}

TEST(ModelScanTest, FkArmPointsLieOnTheirLinks) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf", {}, &model).ok());
  const std::vector<double> q = RandomJointValues(model, 3);
  CheckPointsOnTheirMeshes(model, q, PoseFromXyYaw(0.3, -0.2, 0.4), 0.002, 3, 50000);
}

TEST(ModelScanTest, KukaPointsLieOnTheirLinks) {
  const std::string urdf =
      std::string(EDGEFIT_SHARED_DIR) + "/robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf";
  if (!std::filesystem::exists(urdf)) GTEST_SKIP() << urdf << " absent";
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(urdf, {}, &model).ok());
  const std::vector<double> q = RandomJointValues(model, 11);
  CheckPointsOnTheirMeshes(model, q, PoseFromXyYaw(1.0, 0.5, 0.3), 0.006, 2, 20000);
}

}  // namespace
}  // namespace edgefit
