// The world and its clearance from a virtual scan whose every object is
// known: the bundled robot at a known posture before a fence panel, beside
// a pillar and a crate, on the floor, scanned from three stations by the
// virtual scanner with mixed pixels and incidence noise; the world built as
// `edgefit world` builds it (WorldBackground, WritePlanningWorld) with the
// robot where it stands. The truth is the scene's geometry: the least
// distance from the robot's moving links (2 mm samples of their surfaces)
// to the objects' boxes and the floor.
//   - As scanned, the clearance matches the truth within its stated
//     tolerance (clearance.h): never shorter than it by more than a voxel's
//     diagonal plus the scan's noise, never longer by more than the noise.
//   - Leaning the arm toward the fence: a waypoint whose true gap is 60 mm
//     is free; one 30 mm into the fence is flagged, on that waypoint, where
//     the arm truly reaches the fence's voxels.
//   - With its dress pack scanned on it (harnesses, hoses, covers, brackets,
//     which edgefit world gives to the links), the robot as scanned and
//     turned 3 deg at joint_1 does not meet its own ghost.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/scanner/asset_scan.h"
#include "edgefit/scanner/virtual_scanner.h"
#include "edgefit/scene/accessories.h"
#include "edgefit/scene/environment.h"
#include "edgefit/scene/model_scene.h"
#include "edgefit/world/clearance.h"
#include "edgefit/world/planning_world.h"
#include "edgefit/world/world_background.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

constexpr double kSceneVoxel = 0.02;
constexpr double kSceneNoise = 0.005;  // [m] the scan's noise and registration, at most
const double kSceneDiagonal = std::sqrt(3.0) * kSceneVoxel;

struct KnownBox {
  const char* kind;
  Eigen::Vector3d centre, size;  // world frame, axis-aligned [m]

  double Distance(const Eigen::Vector3d& p) const {
    return ((p - centre).cwiseAbs() - 0.5 * size).cwiseMax(0.0).norm();
  }
};

class ScannedWorldE2eTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("edgefit_scanned_world_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                   ModelLoadOptions(), &model_)
                    .ok());
    q_ = model_.ZeroJoints();
    ASSERT_TRUE(model_.ResolveDependentJoints(&q_).ok());
    // The moving links' surfaces, link frame.
    std::vector<bool> moving(model_.links().size(), false);
    for (const int j : model_.joint_order()) {
      const Joint& joint = model_.joints()[static_cast<size_t>(j)];
      moving[static_cast<size_t>(joint.child_link)] =
          joint.IsMoving() || moving[static_cast<size_t>(joint.parent_link)];
    }
    for (size_t l = 0; l < model_.links().size(); ++l) {
      if (!moving[l] || model_.links()[l].mesh.empty()) continue;
      samples_.emplace_back(l, SampleMeshSurface(model_.links()[l].mesh, 0.002, 1).points);
    }
    // The fence 120 mm beyond the arm's reach as it stands, a pillar to its
    // right, a crate behind it.
    fence_face_ = MaxX(0.0) + 0.12;
    boxes_ = {{"fence", {fence_face_ + 0.02, 0.0, 1.2}, {0.04, 3.0, 2.4}},
              {"pillar", {0.4, -1.3, 1.5}, {0.3, 0.3, 3.0}},
              {"crate", {-1.1, 1.0, 0.3}, {0.6, 0.5, 0.6}}};
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<Pose> Posed(double joint_1, double joint_2) const {
    std::vector<double> q = q_;
    q[static_cast<size_t>(model_.JointIndex("joint_1"))] = joint_1;
    q[static_cast<size_t>(model_.JointIndex("joint_2"))] = joint_2;
    EXPECT_TRUE(model_.ResolveDependentJoints(&q).ok());
    return model_.ForwardKinematics(q);
  }
  // The farthest +x of the moving links' surfaces with joint_2 at a.
  double MaxX(double a) const {
    const std::vector<Pose> T = Posed(0.0, a);
    double x = -1e9;
    for (const auto& [l, points] : samples_) {
      for (const Eigen::Vector3f& p : points) x = std::max(x, (T[l] * p.cast<double>()).x());
    }
    return x;
  }
  // The true clearance with joint_2 at a: the moving links to the boxes and
  // the floor (z = 0).
  double Truth(double a) const {
    const std::vector<Pose> T = Posed(0.0, a);
    double d = 1e9;
    for (const auto& [l, points] : samples_) {
      for (const Eigen::Vector3f& p : points) {
        const Eigen::Vector3d w = T[l] * p.cast<double>();
        d = std::min(d, std::max(w.z(), 0.0));
        for (const KnownBox& box : boxes_) d = std::min(d, box.Distance(w));
      }
    }
    return d;
  }

  // Scans the scene (with the robot's dress pack or not) and writes its
  // world, the robot at its true posture, into dir_/name.
  void ScanAndWriteWorld(bool dress_pack, const std::string& name) {
    const std::vector<Pose> T = model_.ForwardKinematics(q_);
    Scene scene;
    AddModelToScene(model_, T, &scene);
    if (dress_pack) {
      AccessoryOptions accessories;
      accessories.seed = 3;
      AddAccessories(model_, q_, T, accessories, &scene);
    }
    Eigen::AlignedBox3d box = model_.BoundingBox(q_, Pose::Identity());
    for (const KnownBox& b : boxes_) {
      SceneMesh mesh;
      mesh.mesh_world.Append(MakeBoxMesh(b.size), Pose(Eigen::Translation3d(b.centre)));
      mesh.kind = b.kind;
      scene.meshes.push_back(mesh);
      box.extend(b.centre - 0.5 * b.size);
      box.extend(b.centre + 0.5 * b.size);
    }
    EnvironmentOptions environment;
    environment.clutter_count = 0;  // the floor only: the objects are the test's
    AddEnvironment(box, environment, &scene);
    AssetScanOptions sensor;
    ASSERT_TRUE(ApplySensorPreset("mixed_pixels+incidence", &sensor).ok());
    VirtualScanOptions options = sensor.scan;
    options.spacing = 0.004;
    options.asset_box_world = box;
    options.seed = 5;
    // Stations before the robot and to both sides of the fence's near face.
    std::vector<Pose> stations;
    for (const Eigen::Vector3d& at : {Eigen::Vector3d(-2.5, -0.8, 1.6), Eigen::Vector3d(fence_face_ - 1.6, -2.4, 1.4),
                                      Eigen::Vector3d(fence_face_ - 1.6, 2.4, 1.5)}) {
      stations.emplace_back(Eigen::Translation3d(at));
    }
    VirtualScan scan;
    ASSERT_TRUE(ScanScene(scene, stations, options, &scan).ok());

    WorldMachine robot;
    robot.name = "robot";
    robot.model = &model_;
    robot.q = q_;
    std::vector<WorldMachine> machines = {robot};
    std::vector<Eigen::Vector3f> background;
    WorldBackgroundSummary summary;
    ASSERT_TRUE(WorldBackground({0.008}, WorldBackgroundOptions(), &scan.scans, &machines, &background, &summary).ok());
    BackgroundOptions voxels;
    voxels.voxel = kSceneVoxel;
    ASSERT_TRUE(WritePlanningWorld(machines, &background, voxels, (dir_ / name).string(), nullptr).ok());
  }

  fs::path dir_;
  KinematicModel model_;
  std::vector<double> q_;
  std::vector<std::pair<size_t, std::vector<Eigen::Vector3f>>> samples_;
  double fence_face_ = 0.0;
  std::vector<KnownBox> boxes_;
};

TEST_F(ScannedWorldE2eTest, ClearanceMatchesTheSceneAndTheFenceIsHitWhereItStands) {
  ScanAndWriteWorld(/*dress_pack=*/false, "world");
  ClearanceWorld world;
  ASSERT_TRUE(world.Load((dir_ / "world").string(), "robot", 1.0).ok());

  // Leaning toward the fence: the last posture 60 mm short of it (truly),
  // the first 30 mm into it.
  const Joint& joint_2 = model_.joints()[static_cast<size_t>(model_.JointIndex("joint_2"))];
  double pass = 0.0, hit = 0.0;
  for (double a = 0.0; a <= joint_2.upper; a += 0.002) {
    if (MaxX(a) < fence_face_ - 0.06) pass = a;
    if (MaxX(a) > fence_face_ + 0.03) {
      hit = a;
      break;
    }
  }
  ASSERT_GT(hit, pass) << "the arm does not reach the fence";
  std::vector<std::vector<double>> waypoints(3);
  ASSERT_TRUE(world.Posture({}, &waypoints[0]).ok());
  ASSERT_TRUE(world.Posture({{"joint_2", pass}}, &waypoints[1]).ok());
  ASSERT_TRUE(world.Posture({{"joint_2", hit}}, &waypoints[2]).ok());
  const ClearanceOptions options;
  Status status;
  const std::vector<PostureClearance> c = world.Check(waypoints, options, &status);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(c.size(), 3u);

  for (const int k : {0, 1}) {
    const double truth = Truth(k == 0 ? 0.0 : pass);
    SCOPED_TRACE("waypoint " + std::to_string(k) + ", true clearance " + std::to_string(truth));
    EXPECT_FALSE(c[static_cast<size_t>(k)].colliding) << DescribeCollision(c[static_cast<size_t>(k)]);
    EXPECT_LE(c[static_cast<size_t>(k)].distance_to_background, truth + kSceneNoise);
    EXPECT_GE(c[static_cast<size_t>(k)].distance_to_background, truth - kSceneDiagonal - kSceneNoise);
  }
  EXPECT_NEAR(Truth(pass), fence_face_ - MaxX(pass), 1e-6);  // the fence is what is nearest

  // The hit: on waypoint 2, between where the arm truly reaches the fence's
  // nearest voxels (a voxel and the noise before its face) and its face.
  ASSERT_TRUE(c[2].colliding);
  EXPECT_EQ(c[2].collision_b, "background");
  const auto reaches = [&](double x) {
    for (double t = 0.0; t <= 1.0; t += 1e-3) {
      if (MaxX(pass + t * (hit - pass)) >= x) return t;
    }
    return 1.0;
  };
  const double step = options.step_rad / (hit - pass);
  EXPECT_GE(c[2].collision_fraction, reaches(fence_face_ - kSceneVoxel - kSceneNoise) - step);
  EXPECT_LE(c[2].collision_fraction, reaches(fence_face_ + kSceneNoise) + step);
  EXPECT_NEAR(c[2].p_world_collision.x(), fence_face_, kSceneVoxel + kSceneNoise);
}

TEST_F(ScannedWorldE2eTest, TheDressPackIsNoGhost) {
  ScanAndWriteWorld(/*dress_pack=*/true, "dressed");
  ClearanceWorld world;
  ASSERT_TRUE(world.Load((dir_ / "dressed").string(), "robot", 1.0).ok());
  std::vector<std::vector<double>> waypoints(2);
  ASSERT_TRUE(world.Posture({}, &waypoints[0]).ok());
  ASSERT_TRUE(world.Posture({{"joint_1", 3.0 * M_PI / 180.0}}, &waypoints[1]).ok());
  Status status;
  const std::vector<PostureClearance> c = world.Check(waypoints, ClearanceOptions(), &status);
  ASSERT_TRUE(status.ok()) << status.message();
  for (const PostureClearance& at : c) {
    EXPECT_FALSE(at.colliding) << DescribeCollision(at);
    EXPECT_GT(at.distance_to_background, kSceneVoxel) << "its ghost stayed beside it";
  }
}

}  // namespace
}  // namespace edgefit
