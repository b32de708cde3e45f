#include "edgefit/model/kinematic_model.h"

#include <gtest/gtest.h>

#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

const char kFkArm[] = EDGEFIT_SOURCE_DIR "/assets/models/fk_arm.urdf";

Pose Trans(double x, double y, double z) { return Pose(Eigen::Translation3d(x, y, z)); }
Pose Rot(double angle, const Eigen::Vector3d& axis) { return Pose(Eigen::AngleAxisd(angle, axis)); }

void ExpectPoseNear(const Pose& actual, const Pose& expected, double tol) {
  EXPECT_LT((actual.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), tol)
      << "actual\n" << actual.matrix() << "\nexpected\n" << expected.matrix();
}

class FkArmTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(LoadKinematicModel(kFkArm, {}, &model_).ok()); }
  KinematicModel model_;
};

TEST_F(FkArmTest, StructureTypesAndLimits) {
  EXPECT_EQ(model_.name(), "fk_arm");
  ASSERT_EQ(model_.links().size(), 6u);
  ASSERT_EQ(model_.joints().size(), 5u);
  EXPECT_EQ(model_.links()[model_.root_link()].name, "base_link");
  const Joint& j1 = model_.joints()[model_.JointIndex("joint_1")];
  EXPECT_EQ(j1.type, JointType::kRevolute);
  EXPECT_TRUE(j1.axis.isApprox(Eigen::Vector3d::UnitZ()));  // "0 0 2" normalized.
  EXPECT_TRUE(j1.has_limits);
  EXPECT_EQ(j1.lower, -3.0);
  EXPECT_EQ(j1.upper, 3.0);
  const Joint& j3 = model_.joints()[model_.JointIndex("joint_3")];
  EXPECT_EQ(j3.type, JointType::kPrismatic);
  EXPECT_EQ(j3.upper, 0.5);
  const Joint& j4 = model_.joints()[model_.JointIndex("joint_4")];
  EXPECT_EQ(j4.type, JointType::kContinuous);
  EXPECT_FALSE(j4.has_limits);
  EXPECT_STREQ(JointTypeName(model_.joints()[4].type), "fixed");
  EXPECT_EQ(model_.IndependentJoints(), (std::vector<int>{0, 1, 2, 3}));
  // Parents first.
  const std::vector<int>& order = model_.joint_order();
  for (size_t k = 1; k < order.size(); ++k) {
    EXPECT_EQ(model_.joints()[order[k]].parent_link, model_.joints()[order[k - 1]].child_link);
  }
}

TEST_F(FkArmTest, ForwardKinematicsMatchesHandComputedChain) {
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                        Z = Eigen::Vector3d::UnitZ();
  const Pose T_world_root = Trans(1, 2, 0) * Rot(0.4, Z);
  for (const std::vector<double>& q : std::vector<std::vector<double>>{
           {0, 0, 0, 0, 0}, {0.7, -0.3, 0.25, 5.0, 0}, {-2.5, 1.9, 0.5, -7.0, 0}}) {
    const std::vector<Pose> T = model_.ForwardKinematics(q, T_world_root);
    const Pose T1 = T_world_root * Trans(0, 0, 0.2) * Rot(q[0], Z);
    const Pose T2 = T1 * Trans(0.1, 0, 0.5) * Rot(M_PI / 2, Z) * Rot(q[1], Y);
    const Pose T3 = T2 * Trans(0, 0, 0.6) * Trans(q[2], 0, 0);
    const Pose T4 = T3 * Trans(0.2, 0, 0) * Rot(-q[3], Z);  // Axis 0 0 -1.
    const Pose T5 = T4 * Trans(0, 0, 0.1) * Rot(0.3, X);
    ExpectPoseNear(T[model_.LinkIndex("base_link")], T_world_root, 1e-12);
    ExpectPoseNear(T[model_.LinkIndex("link_1")], T1, 1e-12);
    ExpectPoseNear(T[model_.LinkIndex("link_2")], T2, 1e-12);
    ExpectPoseNear(T[model_.LinkIndex("link_3")], T3, 1e-12);
    ExpectPoseNear(T[model_.LinkIndex("link_4")], T4, 1e-12);
    ExpectPoseNear(T[model_.LinkIndex("tool0")], T5, 1e-12);
  }
  // A value checked with pencil: joint_1 = 90 deg turns joint_2's offset
  // (0.1, 0, 0.5) into (0, 0.1, 0.5), on top of the 0.2 m base height.
  const std::vector<Pose> T = model_.ForwardKinematics({M_PI / 2, 0, 0, 0, 0});
  EXPECT_TRUE(T[model_.LinkIndex("link_2")].translation().isApprox(Eigen::Vector3d(0, 0.1, 0.7)));
}

TEST_F(FkArmTest, ZeroJointsClampIntoLimitsAndMeshesMerged) {
  const std::vector<double> zero = model_.ZeroJoints();
  EXPECT_EQ(zero, std::vector<double>(5, 0.0));  // 0 is inside every range here.
  const Link& base = model_.links()[model_.LinkIndex("base_link")];
  EXPECT_EQ(base.visuals.size(), 1u);
  EXPECT_EQ(base.visuals[0].kind, Visual::Kind::kBox);
  EXPECT_EQ(base.visuals[0].triangle_count, 12);
  EXPECT_TRUE(base.mesh.BoundingBox().min().isApprox(Eigen::Vector3d(-0.2, -0.2, 0.0)));
  EXPECT_TRUE(model_.links()[model_.LinkIndex("link_4")].mesh.empty());
  // Zero pose: base box to z 0.2; link_2 box (0.1 wide) from z 0.7 to 1.3;
  // sphere r 0.05 at z 1.3.
  const Eigen::AlignedBox3d bb = model_.BoundingBox(zero);
  EXPECT_NEAR(bb.min().z(), 0.0, 1e-12);
  EXPECT_NEAR(bb.max().z(), 1.35, 1e-12);
  EXPECT_NEAR(bb.max().x(), 0.2, 1e-12);
}

TEST(KinematicModelTest, FinalizeRejectsNonTrees) {
  KinematicModel model;
  model.mutable_links().resize(3);
  model.mutable_links()[0].name = "a";
  model.mutable_links()[1].name = "b";
  model.mutable_links()[2].name = "c";
  Joint j;
  j.name = "ab";
  j.parent_link = 0;
  j.child_link = 1;
  model.mutable_joints().push_back(j);
  Status status = model.Finalize();
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("two root links"), std::string::npos) << status.message();
  j.name = "bc";
  j.parent_link = 1;
  j.child_link = 2;
  model.mutable_joints().push_back(j);
  EXPECT_TRUE(model.Finalize().ok());
  j.name = "ac";
  j.parent_link = 0;
  model.mutable_joints().push_back(j);
  status = model.Finalize();
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("child of two joints"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace edgefit
