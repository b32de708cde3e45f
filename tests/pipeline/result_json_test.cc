// result.json (result_json.h) of fits that did not run to the end.
#include "edgefit/pipeline/result_json.h"

#include <gtest/gtest.h>

#include <vector>

#include "edgefit/pipeline/asset_kind.h"
#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

// The bundled robot with its gun, loaded once.
const KinematicModel& Robot() {
  static const KinematicModel* model = [] {
    auto* loaded = new KinematicModel();
    std::vector<double> q;
    testing_util::LoadBundledRobotWithGun("", loaded, &q);
    return loaded;
  }();
  return *model;
}

// result.json of a fit that stopped at the base's rough stage (as Fit()
// leaves it: zero joints, no bodies, no covariance): every spread null,
// every joint not seen.
// Reading the covariance that never ran crashed edgefit fit on a scan of
// an ABB IRB 6700's base alone.
TEST(ResultJsonTest, ResultJsonOfAFitStoppedBeforeTheChain) {
  const KinematicModel& model = Robot();
  FitResult fit;
  fit.q = model.ZeroJoints();
  fit.message = "base rough registration: no corners in the scan's cross-sections";
  const nlohmann::json result = FitResultJson(model, AssetKind::kArticulated, FitOptions(), fit);
  EXPECT_FALSE(result["joint_std"].empty());
  for (const auto& [joint, std] : result["joint_std"].items()) EXPECT_TRUE(std.is_null()) << joint;
  EXPECT_EQ(result["joint_status"].size(), result["joint_std"].size());
  for (const auto& [joint, verdict] : result["joint_status"].items()) {
    EXPECT_EQ(verdict["verdict"], "not_seen") << joint;
    EXPECT_TRUE(verdict["std"].is_null()) << joint;
  }
  EXPECT_FALSE(result["quality"]["ok"].get<bool>());
}

// A round joint fitted with a partner that has two values names it.
TEST(ResultJsonTest, ATornPairNamesThePartner) {
  const KinematicModel& model = Robot();
  FitResult fit;
  fit.q = model.ZeroJoints();
  BodyQuality torn;
  torn.link = "link_4";
  torn.joint = "joint_4";
  torn.verdict = JointVerdict::kAmbiguous;
  torn.partner_torn = true;
  torn.torn_partner = "joint_5";
  fit.bodies.push_back(torn);
  const nlohmann::json result = FitResultJson(model, AssetKind::kArticulated, FitOptions(), fit);
  const nlohmann::json& status = result["joint_status"]["joint_4"];
  EXPECT_EQ(status["verdict"], "ambiguous");
  EXPECT_EQ(status["reason"], "the joint swept with it has two values that fit about as well");
  EXPECT_EQ(status["partner"], "joint_5");
  EXPECT_TRUE(status["alternatives"].empty());
  EXPECT_FALSE(result["joint_status"]["joint_3"].contains("partner"));
}

}  // namespace
}  // namespace edgefit
