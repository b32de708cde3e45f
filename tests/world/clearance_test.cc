// edgefit clearance against the truth of a scene it is given: the bundled
// robot before a wall of points at a known place. The distance to the wall
// as scanned, a waypoint that passes it and one that hits it (on the right
// waypoint, at the right place on the way), and the robot's own ghost
// (points on its surface left in the background) carved away. The world's
// truth measures at their thresholds.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "edgefit/model/urdf_loader.h"
#include "edgefit/world/background_voxels.h"
#include "edgefit/world/clearance.h"
#include "edgefit/world/floating_voxels.h"
#include "edgefit/world/planning_world.h"
#include "edgefit/world/world_truth.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

constexpr double kVoxel = 0.02;

class ClearanceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test and process: ctest runs this fixture's tests in
    // parallel, and one's TearDown must not remove another's world.
    dir_ = fs::temp_directory_path() /
           ("edgefit_clearance_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                   ModelLoadOptions(), &model_)
                    .ok());
    joint_2_ = model_.JointIndex("joint_2");
    ASSERT_GE(joint_2_, 0);
    q_ = model_.ZeroJoints();
    ASSERT_TRUE(model_.ResolveDependentJoints(&q_).ok());
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The farthest +x of the links that move off the base, at joint_2 = a.
  double MaxX(double a) const {
    std::vector<double> q = q_;
    q[static_cast<size_t>(joint_2_)] = a;
    EXPECT_TRUE(model_.ResolveDependentJoints(&q).ok());
    const std::vector<Pose> T = model_.ForwardKinematics(q);
    double x = -1e9;
    for (size_t l = 0; l < model_.links().size(); ++l) {
      if (static_cast<int>(l) == model_.root_link() || model_.links()[l].mesh.empty()) continue;
      x = std::max(x, model_.links()[l].mesh.BoundingBox(T[l]).max().x());
    }
    return x;
  }

  // The robot as scanned before `points`, in dir_/world.
  Status WriteWorld(const std::vector<Eigen::Vector3f>& points) const {
    WorldMachine machine;
    machine.name = "robot";
    machine.model = &model_;
    machine.q = q_;
    BackgroundOptions background;
    background.voxel = kVoxel;
    return WritePlanningWorld({machine}, &points, background, (dir_ / "world").string(), nullptr);
  }

  fs::path dir_;
  KinematicModel model_;
  int joint_2_ = -1;
  std::vector<double> q_;
};

TEST_F(ClearanceTest, WallAtAKnownDistance) {
  // A wall of points (10 mm apart) in the plane x = wall, in the middle of
  // a voxel: its voxels' near face is x = face, 10 mm before it.
  const double as_scanned = MaxX(0.0);
  const double face = std::ceil((as_scanned + 0.15) / kVoxel) * kVoxel;
  const double wall = face + 0.5 * kVoxel;
  std::vector<Eigen::Vector3f> points;
  for (double y = -3.0; y <= 3.0; y += 0.01) {
    for (double z = 0.0; z <= 3.0; z += 0.01) points.emplace_back(wall, y, z);
  }
  // The robot's own ghost: points on its surface as scanned.
  const std::vector<Pose> T = model_.ForwardKinematics(q_);
  for (size_t l = 0; l < model_.links().size(); ++l) {
    for (const Eigen::Vector3d& v : model_.links()[l].mesh.vertices) {
      points.push_back((T[l] * v).cast<float>());
    }
  }
  const Status written = WriteWorld(points);
  ASSERT_TRUE(written.ok()) << written.message();

  ClearanceWorld world;
  ASSERT_TRUE(world.Load((dir_ / "world").string(), "robot", 1.0).ok());
  ASSERT_EQ(world.machines(), std::vector<std::string>{"robot"});
  // Waypoints along joint_2 (leaning the arm to +x): one that passes 30 mm
  // before the wall's voxels, then one 30 mm into them.
  double pass = 0.0, hit = 0.0;
  const Joint& joint = model_.joints()[static_cast<size_t>(joint_2_)];
  for (double a = 0.0; a <= joint.upper; a += 0.002) {
    if (MaxX(a) < face - 0.03) pass = a;
    if (MaxX(a) > face + 0.03) {
      hit = a;
      break;
    }
  }
  ASSERT_GT(hit, pass) << "the arm does not reach the wall";
  std::vector<std::vector<double>> waypoints(3);
  ASSERT_TRUE(world.Posture({}, &waypoints[0]).ok());
  ASSERT_TRUE(world.Posture({{"joint_2", pass}}, &waypoints[1]).ok());
  ASSERT_TRUE(world.Posture({{"joint_2", hit}}, &waypoints[2]).ok());
  ClearanceOptions options;
  Status status;
  const std::vector<PostureClearance> c = world.Check(waypoints, options, &status);
  ASSERT_TRUE(status.ok()) << status.message();
  ASSERT_EQ(c.size(), 3u);
  // As scanned: the distance to the voxels' face, not to the ghost.
  EXPECT_FALSE(c[0].colliding) << c[0].collision_a << " with " << c[0].collision_b;
  EXPECT_NEAR(c[0].distance_to_background, face - as_scanned, 1e-4);
  EXPECT_LE(c[0].distance_to_background, wall - as_scanned);  // never longer than to the points
  EXPECT_FALSE(c[1].colliding);
  EXPECT_NEAR(c[1].distance_to_background, face - MaxX(pass), 1e-4);
  EXPECT_TRUE(std::isinf(c[0].distance_to_machines));  // no other machine
  // The hit: on waypoint 2, on the way there, where the arm truly reaches
  // the face (within one step of the check).
  ASSERT_TRUE(c[2].colliding);
  EXPECT_EQ(c[2].collision_b, "background");
  EXPECT_EQ(c[2].collision_a.rfind("robot_", 0), 0u) << c[2].collision_a;
  double truth = 1.0;
  for (double t = 0.0; t <= 1.0; t += 1e-3) {
    if (MaxX(pass + t * (hit - pass)) >= face) {
      truth = t;
      break;
    }
  }
  EXPECT_LT(truth, 1.0);
  const double step = options.step_rad / (hit - pass);
  EXPECT_NEAR(c[2].collision_fraction, truth, step + 1e-3);
  EXPECT_NEAR(c[2].p_world_collision.x(), face, 1e-3);
  EXPECT_EQ(c[2].distance_to_background, 0.0);

  // Bad postures: one line.
  std::vector<double> q;
  EXPECT_NE(world.Posture({{"joint_9", 0.0}}, &q).message().find("joint 'joint_9': not a joint"),
            std::string::npos);
  EXPECT_NE(world.Posture({{"joint_2", 9.0}}, &q).message().find("outside its limits"),
            std::string::npos);
  ClearanceWorld other;
  EXPECT_NE(other.Load((dir_ / "world").string(), "left", 1.0).message().find("no machine 'left' (the world holds: robot)"),
            std::string::npos);
}

// The world's truth measures (world_truth.h), exact at their thresholds:
// points just inside and just outside each reach of the files' surfaces.
TEST_F(ClearanceTest, TruthMeasuresAtTheirThresholds) {
  const double face = std::ceil((MaxX(0.0) + 0.15) / kVoxel) * kVoxel;
  const double wall = face + 0.5 * kVoxel;
  std::vector<Eigen::Vector3f> points;
  for (double y = -3.0; y <= 3.0; y += 0.01) {
    for (double z = 0.0; z <= 3.0; z += 0.01) points.emplace_back(wall, y, z);
  }
  const Status written = WriteWorld(points);
  ASSERT_TRUE(written.ok()) << written.message();
  // The robot's highest and lowest surface points.
  const std::vector<Pose> T = model_.ForwardKinematics(q_);
  Eigen::Vector3d top(0, 0, -1e9), bottom(0, 0, 1e9);
  for (size_t l = 0; l < model_.links().size(); ++l) {
    for (const Eigen::Vector3d& v : model_.links()[l].mesh.vertices) {
      const Eigen::Vector3d w = T[l] * v;
      if (w.z() > top.z()) top = w;
      if (w.z() < bottom.z()) bottom = w;
    }
  }
  TruthPoints truth;
  const auto add = [&](const Eigen::Vector3d& p, TruthKind kind) {
    truth.points.push_back(p.cast<float>());
    truth.kinds.push_back(kind);
  };
  for (int i = 0; i < 100; ++i) add({wall, -0.01 * i, 1.0}, TruthKind::kBackground);   // on the wall
  add({face - 0.029, 0.5, 1.0}, TruthKind::kBackground);                                // 29 mm before it
  add({face - 0.031, 0.5, 1.0}, TruthKind::kBackground);                                // 31 mm
  add(bottom, TruthKind::kBackground);  // on the robot, far from its points: taken
  add(top + Eigen::Vector3d(0, 0, 0.0099), TruthKind::kMachine);
  add(top + Eigen::Vector3d(0, 0, 0.0101), TruthKind::kMachine);
  add({wall, 2.5, 2.5}, TruthKind::kMachine);  // a machine point in the wall: a ghost
  add(top + Eigen::Vector3d(0, 0, 0.0299), TruthKind::kAccessory);
  add(top + Eigen::Vector3d(0, 0, 0.0301), TruthKind::kAccessory);
  WorldTruthScore score;
  ASSERT_TRUE(ScoreWorldTruth(truth, (dir_ / "world").string(), WorldTruthOptions(), &score).ok());
  EXPECT_EQ(score.background, 103u);
  EXPECT_EQ(score.machine, 3u);
  EXPECT_EQ(score.accessory, 2u);
  EXPECT_DOUBLE_EQ(score.background_covered, 101.0 / 103.0);
  EXPECT_DOUBLE_EQ(score.machines_in_background, 1.0 / 5.0);
  EXPECT_DOUBLE_EQ(score.machine_covered, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(score.accessory_covered, 1.0 / 2.0);
  EXPECT_EQ(score.far_background, 103u);
  EXPECT_DOUBLE_EQ(score.far_background_on_machines, 1.0 / 103.0);
  // A world folder without its files: an error naming the file.
  EXPECT_NE(ScoreWorldTruth(truth, (dir_ / "none").string(), WorldTruthOptions(), &score).message().find("background.bt"),
            std::string::npos);
}

}  // namespace
}  // namespace edgefit

namespace edgefit {
namespace {

// Pieces of the background beside a machine: one floating alone beside the
// arm leaves; one standing on the floor beside it, and one floating far
// from it, stay.
TEST(FloatingVoxelsTest, OnlyWhatFloatsBesideAMachineLeaves) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                 ModelLoadOptions(), &model)
                  .ok());
  WorldMachine machine;
  machine.name = "robot";
  machine.model = &model;
  machine.q = model.ZeroJoints();
  ASSERT_TRUE(model.ResolveDependentJoints(&machine.q).ok());
  const Eigen::AlignedBox3d arm = model.BoundingBox(machine.q);
  const double v = kVoxel;
  std::vector<Eigen::Vector3f> points;
  const auto blob = [&](const Eigen::Vector3d& at, int n) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) points.push_back((at + Eigen::Vector3d(i, j, 0) * 0.5 * v).cast<float>());
    }
  };
  // 0.1 m beyond the arm's farthest point along +x.
  Eigen::Vector3d beside = Eigen::Vector3d::Constant(-1e9);
  const std::vector<Pose> T = model.ForwardKinematics(machine.q);
  for (size_t l = 0; l < model.links().size(); ++l) {
    for (const Eigen::Vector3d& p : model.links()[l].mesh.vertices) {
      if ((T[l] * p).x() > beside.x()) beside = T[l] * p;
    }
  }
  beside.x() += 0.1;
  blob(beside, 4);                                              // floats beside the arm
  // A post beside it on a floor that reaches beyond.
  for (double z = 0.0; z <= arm.center().z(); z += 0.5 * v) {
    points.emplace_back(static_cast<float>(arm.min().x() - 0.1), static_cast<float>(arm.center().y()),
                        static_cast<float>(z));
  }
  for (double x = arm.min().x() - 1.0; x <= arm.min().x() - 0.1; x += 0.5 * v) {
    points.emplace_back(static_cast<float>(x), static_cast<float>(arm.center().y()), 0.0f);
  }
  blob(Eigen::Vector3d(arm.max().x() + 3.0, 0.0, 1.0), 4);      // floats far away
  const std::vector<std::array<int32_t, 3>> voxels = OccupiedVoxels(points, v);
  const std::vector<std::array<int32_t, 3>> floating = FloatingVoxels({machine}, voxels, v, 0.3);
  const std::vector<std::array<int32_t, 3>> alone = OccupiedVoxels(
      std::vector<Eigen::Vector3f>(points.begin(), points.begin() + 16), v);
  EXPECT_EQ(floating, alone);
  EXPECT_GT(voxels.size(), alone.size() + 10);
}

}  // namespace
}  // namespace edgefit
