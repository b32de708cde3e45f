// Joints not trusted for their neighbours' sake (joint_trust.h), on the
// bundled robot's verdicts: below a body that does not match, nothing is
// ok; on a noisy scan a round joint whose partner has two values is not ok,
// on a laser scan (noise_scale 1) it stays ok, and a partner merely not
// pinned leaves it ok; nor is the partner ok when the round joint has two.
#include "edgefit/pipeline/joint_trust.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/bundled_robot_test_util.h"

namespace edgefit {
namespace {

KinematicModel BundledRobot() {
  KinematicModel model;
  std::vector<double> q;
  testing_util::LoadBundledRobotWithGun("", &model, &q);
  return model;
}

// Every joint of the robot ok, joint_3 round (swept with its children),
// joint_4 (its partner) as given.
FitResult Verdicts(const KinematicModel& model, double noise_scale, JointVerdict joint_4,
                   bool joint_4_unpinned) {
  FitResult result;
  result.noise_scale = noise_scale;
  for (const int j : model.joint_order()) {
    const Joint& joint = model.joints()[static_cast<size_t>(j)];
    if (!joint.IsIndependent()) continue;
    BodyQuality b;
    b.joint = joint.name;
    b.link = model.links()[static_cast<size_t>(joint.child_link)].name;
    b.verdict = joint.name == "joint_4" ? joint_4 : JointVerdict::kOk;
    b.unpinned = joint.name == "joint_4" && joint_4_unpinned;
    b.symmetric = joint.name == "joint_3";
    b.ok = b.verdict == JointVerdict::kOk;
    result.bodies.push_back(b);
  }
  return result;
}

const BodyQuality& Of(const FitResult& result, const std::string& joint) {
  for (const BodyQuality& b : result.bodies) {
    if (b.joint == joint) return b;
  }
  ADD_FAILURE() << joint;
  return result.bodies.front();
}

TEST(JointTrustTest, NothingOkBelowABodyThatDoesNotMatch) {
  const KinematicModel model = BundledRobot();
  FitResult result = Verdicts(model, 1.0, JointVerdict::kMismatch, false);
  DistrustBelowUnmatched(model, &result);
  EXPECT_EQ(Of(result, "joint_3").verdict, JointVerdict::kOk);
  EXPECT_EQ(Of(result, "joint_4").verdict, JointVerdict::kMismatch);
  for (const char* below : {"joint_5", "joint_6", "gun_joint"}) {
    EXPECT_EQ(Of(result, below).verdict, JointVerdict::kAmbiguous) << below;
    EXPECT_TRUE(Of(result, below).chain_unmatched) << below;
    EXPECT_FALSE(Of(result, below).ok) << below;
  }
}

TEST(JointTrustTest, ARoundJointIsNotOkWhenItsPartnerHasTwoValuesOnANoisyScan) {
  const KinematicModel model = BundledRobot();
  FitResult noisy = Verdicts(model, 2.0, JointVerdict::kAmbiguous, false);
  DistrustTornPairs(model, &noisy);
  EXPECT_EQ(Of(noisy, "joint_3").verdict, JointVerdict::kAmbiguous);
  EXPECT_TRUE(Of(noisy, "joint_3").partner_torn);
  EXPECT_FALSE(Of(noisy, "joint_3").ok);
  EXPECT_EQ(Of(noisy, "joint_2").verdict, JointVerdict::kOk);  // not round

  FitResult laser = Verdicts(model, 1.0, JointVerdict::kAmbiguous, false);
  DistrustTornPairs(model, &laser);
  EXPECT_EQ(Of(laser, "joint_3").verdict, JointVerdict::kOk);

  FitResult unpinned = Verdicts(model, 2.0, JointVerdict::kAmbiguous, true);
  DistrustTornPairs(model, &unpinned);
  EXPECT_EQ(Of(unpinned, "joint_3").verdict, JointVerdict::kOk);
}

TEST(JointTrustTest, APartnerIsNotOkWhenItsRoundJointHasTwoValuesOnANoisyScan) {
  const KinematicModel model = BundledRobot();
  for (const double noise_scale : {1.0, 2.0}) {
    FitResult result = Verdicts(model, noise_scale, JointVerdict::kOk, false);
    for (BodyQuality& b : result.bodies) {
      if (b.joint != "joint_3") continue;
      b.verdict = JointVerdict::kAmbiguous;  // two values of its own
      b.ok = false;
    }
    DistrustTornPairs(model, &result);
    const BodyQuality& partner = Of(result, "joint_4");
    if (noise_scale > 1.0) {
      EXPECT_EQ(partner.verdict, JointVerdict::kAmbiguous);
      EXPECT_TRUE(partner.partner_torn);
      EXPECT_EQ(partner.torn_partner, "joint_3");
      EXPECT_FALSE(partner.ok);
    } else {
      EXPECT_EQ(partner.verdict, JointVerdict::kOk);
    }
    EXPECT_EQ(Of(result, "joint_5").verdict, JointVerdict::kOk);  // not its partner
    EXPECT_EQ(Of(result, "joint_3").verdict, JointVerdict::kAmbiguous);
    EXPECT_FALSE(Of(result, "joint_3").partner_torn);
  }
}

}  // namespace
}  // namespace edgefit
