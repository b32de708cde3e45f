#include "edgefit/scene/model_scene.h"

#include <gtest/gtest.h>

#include "edgefit/model/urdf_loader.h"
#include "edgefit/scene/main_chain.h"

namespace edgefit {
namespace {

KinematicModel LoadAsset(const std::string& name) {
  KinematicModel model;
  const Status status = LoadKinematicModel(
      std::string(EDGEFIT_SOURCE_DIR) + "/assets/models/" + name, ModelLoadOptions(), &model);
  EXPECT_TRUE(status.ok()) << status.message();
  return model;
}

TEST(ModelSceneTest, OneLabelledMeshPerLinkWithAMesh) {
  const KinematicModel model = LoadAsset("balancer_arm.urdf");
  std::vector<double> q = model.ZeroJoints();
  q[model.JointIndex("joint_1")] = 0.5;
  q[model.JointIndex("joint_2")] = 0.3;
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  const Pose T_world_root = PoseFromXyYaw(1.0, 2.0, 0.3);
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_root);
  Scene scene;
  AddModelToScene(model, T_world_link, &scene);
  ASSERT_EQ(scene.meshes.size(), model.links().size());  // every link has a visual
  for (const SceneMesh& mesh : scene.meshes) {
    ASSERT_GE(mesh.link, 0);
    EXPECT_EQ(mesh.label, LinkLabel(mesh.link));
    EXPECT_EQ(mesh.kind, "link");
    const TriangleMesh& link_mesh = model.links()[mesh.link].mesh;
    ASSERT_EQ(mesh.mesh_world.vertices.size(), link_mesh.vertices.size());
    EXPECT_TRUE(mesh.mesh_world.vertices[0].isApprox(T_world_link[mesh.link] * link_mesh.vertices[0]));
  }
}

TEST(MainChainTest, BalancerArmChainIsTheArmNotTheBalancer) {
  const KinematicModel model = LoadAsset("balancer_arm.urdf");
  const std::vector<int> chain = MainChainLinks(model);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[0], model.LinkIndex("base_link"));
  EXPECT_EQ(chain[1], model.LinkIndex("link_1"));
  EXPECT_EQ(chain[2], model.LinkIndex("link_2"));
}

TEST(MainChainTest, RealRobotChainEndsAtTheLastMeshLink) {
  const std::string path =
      std::string(EDGEFIT_SHARED_DIR) + "/robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf";
  KinematicModel model;
  ModelLoadOptions options;
  if (!LoadKinematicModel(path, options, &model).ok()) GTEST_SKIP() << "no " << path;
  const std::vector<int> chain = MainChainLinks(model);
  ASSERT_EQ(chain.size(), 7u);
  EXPECT_EQ(model.links()[chain.front()].name, "base_link");
  EXPECT_EQ(model.links()[chain.back()].name, "link_6");
}

}  // namespace
}  // namespace edgefit
