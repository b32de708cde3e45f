// AddAccessories on the real robots in ${EDGEFIT_SHARED_DIR}/robots
// (skipped when absent).
#include <gtest/gtest.h>

#include "accessory_checks.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scene/accessories.h"

namespace edgefit {
namespace {

using testing_scene::MakeAccessoryScene;
using testing_scene::PosedScene;

class RobotAccessoriesTest : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    const std::string path =
        std::string(EDGEFIT_SHARED_DIR) + "/robots/" + GetParam() + "/" + GetParam() + ".urdf";
    if (!LoadKinematicModel(path, ModelLoadOptions(), &model_).ok()) {
      GTEST_SKIP() << "no robot at " << path;
    }
    // A working posture: shoulder forward, elbow bent, wrist turned.
    q_ = model_.ZeroJoints();
    const double posture[] = {0.3, -0.5, 0.6, 0.8, 0.7, -0.4};
    const std::vector<int> joints = model_.IndependentJoints();
    for (size_t i = 0; i < joints.size() && i < 6; ++i) {
      const Joint& joint = model_.joints()[joints[i]];
      double value = posture[i];
      if (joint.has_limits) value = std::clamp(value, joint.lower, joint.upper);
      q_[joints[i]] = value;
    }
    ASSERT_TRUE(model_.ResolveDependentJoints(&q_).ok());
  }
  KinematicModel model_;
  std::vector<double> q_;
};

TEST_P(RobotAccessoriesTest, AccessoriesLikeOnARealRobot) {
  const AccessoryOptions options;
  const PosedScene posed = MakeAccessoryScene(model_, q_, options);
  std::cout << GetParam() << ": " << posed.report.BriefReport() << ", link area "
            << posed.link_area << " m^2\n";
  for (const AccessoryRecord& record : posed.report.records) {
    if (record.kind == "bracket") continue;
    std::cout << "  " << record.kind << " r=" << record.radius << " area=" << record.area
              << " links";
    for (int link : record.links) std::cout << " " << model_.links()[link].name;
    std::cout << "\n";
  }
  EXPECT_EQ(posed.report.harnesses, options.harness_count);
  EXPECT_EQ(posed.report.hoses, options.hose_count);
  EXPECT_GE(posed.report.covers, 1);
  EXPECT_GE(posed.report.brackets, 3);
  testing_scene::ExpectHarnessesLikeReal(posed, options);
  const double fraction = posed.report.area / posed.link_area;
  EXPECT_GE(fraction, 0.05);
  EXPECT_LE(fraction, 0.30);
}

TEST_P(RobotAccessoriesTest, SitOnTheLinksWithoutCuttingIn) {
  const PosedScene posed = MakeAccessoryScene(model_, q_, AccessoryOptions());
  testing_scene::ExpectAccessoriesWellPlaced(model_, posed, 0.03);
}

TEST_P(RobotAccessoriesTest, Deterministic) {
  AccessoryOptions options;
  options.seed = 5;
  const PosedScene a = MakeAccessoryScene(model_, q_, options);
  const PosedScene b = MakeAccessoryScene(model_, q_, options);
  testing_scene::ExpectSameScene(a.scene, b.scene);
}

INSTANTIATE_TEST_SUITE_P(Robots, RobotAccessoriesTest,
                         ::testing::Values("kuka_kr150r3100_2", "abb_irb6700_200_260",
                                           "fanuc_m900ib700"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('_', 5));
                         });

}  // namespace
}  // namespace edgefit
