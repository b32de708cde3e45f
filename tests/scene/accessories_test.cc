#include "edgefit/scene/accessories.h"

#include <gtest/gtest.h>

#include "accessory_checks.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

using testing_scene::MakeAccessoryScene;
using testing_scene::PosedScene;

class AccessoriesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const Status status = LoadKinematicModel(
        std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/balancer_arm.urdf", ModelLoadOptions(),
        &model_);
    ASSERT_TRUE(status.ok()) << status.message();
    q_ = model_.ZeroJoints();
    q_[model_.JointIndex("joint_1")] = 0.4;
    q_[model_.JointIndex("joint_2")] = 0.5;
    ASSERT_TRUE(model_.ResolveDependentJoints(&q_).ok());
  }
  KinematicModel model_;
  std::vector<double> q_;
};

TEST_F(AccessoriesTest, AddsEveryKindWithItsLabel) {
  const AccessoryOptions options;
  const PosedScene posed = MakeAccessoryScene(model_, q_, options);
  const AccessoryReport& report = posed.report;
  EXPECT_EQ(report.harnesses, options.harness_count);
  EXPECT_EQ(report.hoses, options.hose_count);
  EXPECT_GE(report.covers, 1);
  EXPECT_GE(report.brackets, options.bracket_count / 2);
  EXPECT_EQ(static_cast<int>(report.records.size()),
            report.harnesses + report.hoses + report.covers + report.brackets);
  EXPECT_EQ(posed.scene.meshes.size(), report.records.size());
  EXPECT_FALSE(report.BriefReport().empty());
  std::cout << "balancer_arm: " << report.BriefReport() << ", link area " << posed.link_area
            << " m^2\n";
}

TEST_F(AccessoriesTest, SitOnTheLinksWithoutCuttingIn) {
  const PosedScene posed = MakeAccessoryScene(model_, q_, AccessoryOptions());
  testing_scene::ExpectAccessoriesWellPlaced(model_, posed, 0.02);
}

TEST_F(AccessoriesTest, HarnessesHaveRealRadiiAndCrossJoints) {
  const AccessoryOptions options;
  const PosedScene posed = MakeAccessoryScene(model_, q_, options);
  ASSERT_GT(posed.report.harnesses, 0);
  testing_scene::ExpectHarnessesLikeReal(posed, options);
}

TEST_F(AccessoriesTest, AreaIsAMeaningfulFractionOfTheRobot) {
  const PosedScene posed = MakeAccessoryScene(model_, q_, AccessoryOptions());
  const double fraction = posed.report.area / posed.link_area;
  EXPECT_GE(fraction, 0.05);
  EXPECT_LE(fraction, 0.45);  // a small model (1.8 m^2): tubes and clamps weigh more
}

TEST_F(AccessoriesTest, DeterministicForASeedDifferentForAnother) {
  AccessoryOptions options;
  options.seed = 11;
  const PosedScene a = MakeAccessoryScene(model_, q_, options);
  const PosedScene b = MakeAccessoryScene(model_, q_, options);
  testing_scene::ExpectSameScene(a.scene, b.scene);
  options.seed = 12;
  const PosedScene c = MakeAccessoryScene(model_, q_, options);
  bool differs = a.scene.meshes.size() != c.scene.meshes.size();
  for (size_t i = 0; !differs && i < a.scene.meshes.size(); ++i) {
    differs = a.scene.meshes[i].mesh_world.vertices != c.scene.meshes[i].mesh_world.vertices;
  }
  EXPECT_TRUE(differs);
}

TEST_F(AccessoriesTest, CountsFollowTheOptions) {
  AccessoryOptions options;
  options.harness_count = 0;
  options.hose_count = 0;
  options.cover_count = 0;
  options.bracket_count = 0;
  PosedScene posed = MakeAccessoryScene(model_, q_, options);
  EXPECT_TRUE(posed.scene.meshes.empty());
  EXPECT_EQ(posed.report.area, 0.0);
  options.harness_count = 3;
  posed = MakeAccessoryScene(model_, q_, options);
  EXPECT_EQ(posed.report.harnesses, 3);
  EXPECT_GE(posed.report.brackets, 1);  // clamps
}

TEST(AccessoryOptionsTest, Validation) {
  std::string error;
  EXPECT_TRUE(AccessoryOptions().IsValid(&error));
  AccessoryOptions bad;
  bad.harness_radius_min = 0.03;
  EXPECT_FALSE(bad.IsValid(&error));
  bad = AccessoryOptions();
  bad.tube_segments = 2;
  EXPECT_FALSE(bad.IsValid(&error));
  bad = AccessoryOptions();
  bad.sag_fraction_max = 2.0;
  EXPECT_FALSE(bad.IsValid(&error));
}

}  // namespace
}  // namespace edgefit
