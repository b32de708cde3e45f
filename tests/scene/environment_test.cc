#include "edgefit/scene/environment.h"

#include <gtest/gtest.h>

#include "mesh_checks.h"

namespace edgefit {
namespace {

using testing_scene::AllFinite;
using testing_scene::IsClosed;

const Eigen::AlignedBox3d kAssetBox(Eigen::Vector3d(-1.0, -0.8, 0.0), Eigen::Vector3d(1.5, 0.8, 2.5));

Scene MakeEnvironment(uint64_t seed, int clutter = 4) {
  EnvironmentOptions options;
  options.seed = seed;
  options.clutter_count = clutter;
  Scene scene;
  AddEnvironment(kAssetBox, options, &scene);
  return scene;
}

TEST(EnvironmentTest, FloorTopIsAtZeroAndCoversTheAsset) {
  const Scene scene = MakeEnvironment(1);
  ASSERT_FALSE(scene.meshes.empty());
  const SceneMesh& floor = scene.meshes[0];
  EXPECT_EQ(floor.kind, "floor");
  EXPECT_EQ(floor.label, kLabelBackground);
  EXPECT_EQ(floor.link, -1);
  EXPECT_TRUE(IsClosed(floor.mesh_world));
  const Eigen::AlignedBox3d box = floor.mesh_world.BoundingBox();
  EXPECT_DOUBLE_EQ(box.max().z(), 0.0);
  EXPECT_LT(box.min().z(), 0.0);
  EXPECT_LE(box.min().x(), kAssetBox.min().x() - 10.0);
  EXPECT_GE(box.max().y(), kAssetBox.max().y() + 10.0);
}

TEST(EnvironmentTest, ClutterStandsOutsideTheKeepOutAndInsideTheRing) {
  const EnvironmentOptions defaults;
  for (uint64_t seed : {1, 2, 3, 17, 99}) {
    const Scene scene = MakeEnvironment(seed);
    ASSERT_EQ(scene.meshes.size(), 1u + defaults.clutter_count) << "seed " << seed;
    for (size_t i = 1; i < scene.meshes.size(); ++i) {
      const SceneMesh& mesh = scene.meshes[i];
      EXPECT_EQ(mesh.label, kLabelBackground);
      EXPECT_TRUE(mesh.kind == "pillar" || mesh.kind == "pallet" || mesh.kind == "fence")
          << mesh.kind;
      EXPECT_TRUE(AllFinite(mesh.mesh_world));
      const Eigen::AlignedBox3d box = mesh.mesh_world.BoundingBox();
      EXPECT_NEAR(box.min().z(), 0.0, 1e-9) << "stands on the floor";
      const double m = defaults.keep_out_margin;
      const bool outside = box.min().x() >= kAssetBox.max().x() + m ||
                           box.max().x() <= kAssetBox.min().x() - m ||
                           box.min().y() >= kAssetBox.max().y() + m ||
                           box.max().y() <= kAssetBox.min().y() - m;
      EXPECT_TRUE(outside) << mesh.kind << " " << i << " seed " << seed;
      const double r = defaults.clutter_max_distance;
      EXPECT_GE(box.min().x(), kAssetBox.min().x() - r - 1e-9);
      EXPECT_LE(box.max().x(), kAssetBox.max().x() + r + 1e-9);
      EXPECT_GE(box.min().y(), kAssetBox.min().y() - r - 1e-9);
      EXPECT_LE(box.max().y(), kAssetBox.max().y() + r + 1e-9);
    }
  }
}

TEST(EnvironmentTest, AllClutterKindsAppear) {
  const Scene scene = MakeEnvironment(5, 6);
  int pillars = 0, pallets = 0, fences = 0;
  for (const SceneMesh& mesh : scene.meshes) {
    pillars += mesh.kind == "pillar";
    pallets += mesh.kind == "pallet";
    fences += mesh.kind == "fence";
  }
  EXPECT_EQ(pillars, 2);
  EXPECT_EQ(pallets, 2);
  EXPECT_EQ(fences, 2);
}

TEST(EnvironmentTest, SameSeedSameSceneOtherSeedOtherScene) {
  const Scene a = MakeEnvironment(7), b = MakeEnvironment(7), c = MakeEnvironment(8);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].kind, b.meshes[i].kind);
    EXPECT_EQ(a.meshes[i].mesh_world.vertices, b.meshes[i].mesh_world.vertices);
  }
  ASSERT_GE(c.meshes.size(), 2u);
  EXPECT_NE(a.meshes[1].mesh_world.BoundingBox().center(),
            c.meshes[1].mesh_world.BoundingBox().center());
}

TEST(EnvironmentTest, NoClutterNoFloor) {
  EnvironmentOptions options;
  options.clutter_count = 0;
  options.add_floor = false;
  Scene scene;
  AddEnvironment(kAssetBox, options, &scene);
  EXPECT_TRUE(scene.meshes.empty());
}

TEST(EnvironmentTest, OptionsValidation) {
  std::string error;
  EXPECT_TRUE(EnvironmentOptions().IsValid(&error));
  EnvironmentOptions bad;
  bad.keep_out_margin = 5.0;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace edgefit
