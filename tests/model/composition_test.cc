#include "edgefit/model/composition.h"

#include <gtest/gtest.h>

namespace edgefit {
namespace {

const std::string kModels = EDGEFIT_SOURCE_DIR "/assets/models/";

TEST(ParseAttachSpecTest, PathLinkAndOptionalPose) {
  AttachSpec spec;
  ASSERT_TRUE(ParseAttachSpec("tools/eef.urdf@link_6", &spec).ok());
  EXPECT_EQ(spec.path, "tools/eef.urdf");
  EXPECT_EQ(spec.parent_link, "link_6");
  EXPECT_TRUE(spec.T_parent_root.isApprox(Pose::Identity()));
  ASSERT_TRUE(ParseAttachSpec("a@b/eef.urdf@tool0:0.1,-0.2,0.3,0,0,1.5707963267948966", &spec).ok());
  EXPECT_EQ(spec.path, "a@b/eef.urdf");
  EXPECT_EQ(spec.parent_link, "tool0");
  EXPECT_TRUE(spec.T_parent_root.translation().isApprox(Eigen::Vector3d(0.1, -0.2, 0.3)));
  EXPECT_TRUE((spec.T_parent_root.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  for (const char* bad : {"eef.urdf", "eef.urdf@", "@link", "eef.urdf@l:1,2,3", "eef.urdf@l:1,2,3,4,5,x",
                          "eef.urdf@l:1,2,3,4,5,6,7", "eef.urdf@:1,2,3,4,5,6"}) {
    const Status status = ParseAttachSpec(bad, &spec);
    EXPECT_FALSE(status.ok()) << bad;
    EXPECT_NE(status.message().find("FILE.urdf@PARENT_LINK"), std::string::npos) << status.message();
  }
}

TEST(ParseAttachSpecTest, CommaListKeepsPosesTogether) {
  std::vector<AttachSpec> specs;
  ASSERT_TRUE(ParseAttachSpecList("gun.urdf@tool0,cam.urdf@link_3:0,0,0.1,0,0,0.5,x.urdf@link_1", &specs).ok());
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0].path, "gun.urdf");
  EXPECT_EQ(specs[1].parent_link, "link_3");
  EXPECT_TRUE(specs[1].T_parent_root.translation().isApprox(Eigen::Vector3d(0, 0, 0.1)));
  EXPECT_EQ(specs[2].path, "x.urdf");
  EXPECT_EQ(specs[2].parent_link, "link_1");
  ASSERT_TRUE(ParseAttachSpecList("", &specs).ok());
  EXPECT_TRUE(specs.empty());
  EXPECT_FALSE(ParseAttachSpecList("gun.urdf@tool0:1,2", &specs).ok());
  EXPECT_FALSE(ParseAttachSpecList("gun.urdf@tool0,,x.urdf@a", &specs).ok());
}

TEST(AttachModelTest, LoadWithAttachmentsChains) {
  std::vector<AttachSpec> specs;
  ASSERT_TRUE(ParseAttachSpecList(kModels + "simple_tool.urdf@tool0", &specs).ok());
  specs.push_back(specs[0]);
  specs[1].parent_link = "tcp";  // On the first tool.
  specs[1].prefix = "b_";
  KinematicModel model;
  const Status status = LoadModelWithAttachments(kModels + "fk_arm.urdf", specs, {}, &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_GE(model.JointIndex("tcp_to_b_mount"), 0);
  EXPECT_EQ(model.links().size(), 14u);
}

TEST(AttachModelTest, ToolFollowsTheParentLink) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(kModels + "fk_arm.urdf", {}, &model).ok());
  AttachSpec spec;
  ASSERT_TRUE(ParseAttachSpec(kModels + "simple_tool.urdf@tool0:0,0,0.05,0,0,0", &spec).ok());
  const Status status = AttachModel(spec, {}, &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(model.links().size(), 10u);
  const int mount_joint = model.JointIndex("tool0_to_mount");
  ASSERT_GE(mount_joint, 0);
  EXPECT_EQ(model.joints()[mount_joint].type, JointType::kFixed);
  const int tcp = model.LinkIndex("tcp");
  EXPECT_EQ(model.links()[tcp].source, kModels + "simple_tool.urdf");
  EXPECT_EQ(model.links()[model.LinkIndex("link_2")].source, kModels + "fk_arm.urdf");
  // The finger joint is an independent joint of the combined model.
  EXPECT_EQ(model.IndependentJoints().size(), 5u);
  std::vector<double> q(model.joints().size(), 0.0);
  for (double q4 : {0.0, 1.0}) {
    q[model.JointIndex("joint_4")] = q4;
    const std::vector<Pose> T = model.ForwardKinematics(q);
    const Pose T_tool0_tcp = T[model.LinkIndex("tool0")].inverse() * T[tcp];
    EXPECT_TRUE(T_tool0_tcp.translation().isApprox(Eigen::Vector3d(0, 0, 0.3)));
    EXPECT_TRUE(T_tool0_tcp.linear().isApprox(Eigen::Matrix3d::Identity()));
  }
}

TEST(AttachModelTest, NameClashIsAnErrorUnlessPrefixed) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(kModels + "fk_arm.urdf", {}, &model).ok());
  AttachSpec spec;
  spec.path = kModels + "simple_tool.urdf";
  spec.parent_link = "tool0";
  ASSERT_TRUE(AttachModel(spec, {}, &model).ok());
  const size_t links = model.links().size();
  Status status = AttachModel(spec, {}, &model);
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find("link name 'mount' already in the model"), std::string::npos)
      << status.message();
  EXPECT_EQ(model.links().size(), links);  // Unchanged on failure.
  spec.prefix = "second_";
  spec.parent_link = "link_2";
  ASSERT_TRUE(AttachModel(spec, {}, &model).ok());
  EXPECT_GE(model.LinkIndex("second_tcp"), 0);
  EXPECT_GE(model.JointIndex("link_2_to_second_mount"), 0);
  spec.parent_link = "no_such_link";
  spec.prefix = "third_";
  EXPECT_FALSE(AttachModel(spec, {}, &model).ok());
}

}  // namespace
}  // namespace edgefit
