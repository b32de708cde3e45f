// Whole virtual scans as `edgefit scan` makes them (model + accessories +
// floor + clutter, production scene builders), on the bundled benchmark
// assets and on every real model in ../shared/robots: each labelled point lies
// within 3 sigma of a mesh of its own class — its link, an accessory, or the
// background (floor at z = 0, clutter).
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/scanner/random_joints.h"
#include "edgefit/scanner/scanner_placement.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/accessories.h"
#include "edgefit/scene/environment.h"
#include "edgefit/scene/model_scene.h"
#include "scanner/scanner_test_util.h"

namespace edgefit {
namespace {

struct SceneCase {
  const char* name;
  std::string urdf;
  std::string attach;    // --attach syntax, may be empty
  std::string postures;  // postures file; empty: a random posture above the floor
  const char* posture;
};

std::ostream& operator<<(std::ostream& os, const SceneCase& c) { return os << c.name; }

class SceneScanTest : public ::testing::TestWithParam<SceneCase> {};

TEST_P(SceneScanTest, LabelledPointsLieOnMeshesOfTheirClass) {
  const SceneCase& c = GetParam();
  if (!std::filesystem::exists(c.urdf)) GTEST_SKIP() << c.urdf << " absent";
  std::vector<AttachSpec> specs;
  ASSERT_TRUE(ParseAttachSpecList(c.attach, &specs).ok());
  KinematicModel model;
  ASSERT_TRUE(LoadModelWithAttachments(c.urdf, specs, ModelLoadOptions(), &model).ok());
  const Pose T_world_base = PoseFromXyYaw(0.4, -0.3, 0.5);
  std::vector<double> q = model.ZeroJoints();
  if (c.postures.empty()) {
    ASSERT_TRUE(RandomJointValuesAboveFloor(model, T_world_base, 0.0, 21, &q));
  } else {
    ASSERT_TRUE(LoadNamedPosture(c.postures, c.posture, model, &q).ok());
    ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  }
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  const Eigen::AlignedBox3d box = model.BoundingBox(q, T_world_base);

  Scene scene;
  AddModelToScene(model, T_world_link, &scene);
  AccessoryOptions accessories;
  accessories.seed = 4;
  AccessoryReport report;
  AddAccessories(model, q, T_world_link, accessories, &scene, &report);
  EnvironmentOptions environment;
  environment.seed = 4;
  AddEnvironment(box, environment, &scene);
  ScannerPlacementOptions placement;
  placement.seed = 4;
  VirtualScanOptions options;
  options.spacing = 0.005;  // coarser than the default 1.7 mm, to keep the test fast
  VirtualScan scan;
  ASSERT_TRUE(ScanScene(scene, PlaceScanners(box, placement), options, &scan).ok());

  const double r = 3.0 * options.noise_sigma;
  // Grid cell of the proximity test [m]: coarse enough for metre-long triangles
  // (rails, floor-like plates) to stay cheap to index.
  constexpr double kCell = 0.04;
  std::vector<std::unique_ptr<testing_util::MeshProximity>> near_link(model.links().size());
  TriangleMesh accessory_mesh, clutter_mesh;
  for (const SceneMesh& m : scene.meshes) {
    if (m.link >= 0) {
      near_link[m.link] = std::make_unique<testing_util::MeshProximity>(m.mesh_world, r, kCell);
    } else if (m.label == kLabelAccessory) {
      accessory_mesh.Append(m.mesh_world);
    } else if (m.kind != "floor") {
      clutter_mesh.Append(m.mesh_world);
    }
  }
  ASSERT_FALSE(accessory_mesh.empty()) << "no accessories were made";
  const testing_util::MeshProximity near_accessory(accessory_mesh, r, kCell);
  const testing_util::MeshProximity near_clutter(clutter_mesh, r, kCell);

  size_t count[3] = {0, 0, 0}, near[3] = {0, 0, 0};  // link, accessory, background
  for (size_t k = 0; k < scan.scans.scans.size(); ++k) {
    const OrganizedScan& s = scan.scans.scans[k];
    for (size_t i = 0; i < s.size(); ++i) {
      const uint16_t label = scan.labels[k][i] & kLabelMask;
      if (label == kLabelMissing) {
        ASSERT_FALSE(s.IsValid(i));
        continue;
      }
      ASSERT_TRUE(s.IsValid(i));
      const Eigen::Vector3d p = s.PointWorld(i);
      if (IsLinkLabel(label)) {
        ++count[0];
        near[0] += near_link[LinkOfLabel(label)]->Within(p);
      } else if (label == kLabelAccessory) {
        ++count[1];
        near[1] += near_accessory.Within(p);
      } else {
        ASSERT_EQ(label, kLabelBackground);
        ++count[2];
        near[2] += std::abs(p.z()) <= r || near_clutter.Within(p);
      }
    }
  }
  const char* kClass[3] = {"link", "accessory", "background"};
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(kClass[k]);
    EXPECT_GT(count[k], 500u);
    // Gaussian noise along the ray moves a point at most |noise| off its
    // surface: >= 99.73% lie within 3 sigma.
    EXPECT_GE(static_cast<double>(near[k]), 0.997 * static_cast<double>(count[k]))
        << near[k] << " of " << count[k];
  }
}

std::vector<SceneCase> Cases() {
  const std::string assets = EDGEFIT_SOURCE_DIR "/assets/";
  const std::string robots = EDGEFIT_SHARED_DIR "/robots/";
  return {
      {"BundledRobotWithGun", assets + "robot/robot.urdf",
       assets + "robot/weld_gun.urdf@tool0", assets + "robot/postures.json", "weld_low"},
      {"BundledConveyor", assets + "conveyor/conveyor.urdf", "", assets + "conveyor/postures.json",
       "transfer"},
      {"Kuka", robots + "kuka_kr150r3100_2/kuka_kr150r3100_2.urdf",
       robots + "weld_gun_x16005_botrail/weld_gun_x16005_botrail.urdf@tool0", "", ""},
      {"Abb", robots + "abb_irb6700_200_260/abb_irb6700_200_260.urdf", "", "", ""},
      {"Fanuc", robots + "fanuc_m900ib700/fanuc_m900ib700.urdf", "", "", ""},
      {"KukaOnLinearAxis", robots + "kuka_kr150_2_on_linear_axis/kuka_kr150_2_on_linear_axis.urdf",
       "", "", ""},
      {"Positioner", robots + "motoman_motopos_d500/motoman_motopos_d500.urdf", "", "", ""},
  };
}

INSTANTIATE_TEST_SUITE_P(Models, SceneScanTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<SceneCase>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace edgefit
