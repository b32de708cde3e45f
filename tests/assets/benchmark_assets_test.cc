// The committed benchmark models (assets/robot, assets/conveyor): they are
// what the generator writes, byte for byte, and they satisfy the brief of
// paper Fig. 4 / Sec. 7.3: sizes, joint structure, loop closure, postures,
// closed meshes with sharp edges.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "edgefit/assets/benchmark_assets.h"
#include "edgefit/assets/mesh_topology.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/loop_closure.h"
#include "edgefit/model/mesh_loader.h"
#include "edgefit/model/sharp_edges.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

const std::string kAssets = EDGEFIT_SOURCE_DIR "/assets";
const std::string kRobotUrdf = kAssets + "/robot/robot.urdf";
const std::string kGunUrdf = kAssets + "/robot/weld_gun.urdf";
const std::string kConveyorUrdf = kAssets + "/conveyor/conveyor.urdf";

using Posture = std::map<std::string, double>;

std::map<std::string, Posture> ReadPostures(const std::string& path) {
  std::string text;
  EXPECT_TRUE(ReadFileToString(path, &text).ok()) << path;
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  std::map<std::string, Posture> postures;
  if (json.is_discarded() || !json.contains("postures")) {
    ADD_FAILURE() << path << ": not a postures file";
    return postures;
  }
  for (const auto& [name, values] : json["postures"].items()) {
    for (const auto& [joint, value] : values.items()) postures[name][joint] = value.get<double>();
  }
  return postures;
}

// Full joint values for a posture (independent joints set, others resolved).
std::vector<double> PostureJoints(const KinematicModel& model, const Posture& posture) {
  std::vector<double> q = model.ZeroJoints();
  for (const auto& [name, value] : posture) {
    const int j = model.JointIndex(name);
    EXPECT_GE(j, 0) << name;
    if (j >= 0) q[j] = value;
  }
  const Status status = model.ResolveDependentJoints(&q, 1e-9);
  EXPECT_TRUE(status.ok()) << status.message();
  return q;
}

KinematicModel LoadRobotWithGun() {
  AttachSpec gun;
  EXPECT_TRUE(ParseAttachSpec(kGunUrdf + "@tool0", &gun).ok());
  KinematicModel model;
  const Status status = LoadModelWithAttachments(kRobotUrdf, {gun}, ModelLoadOptions(), &model);
  EXPECT_TRUE(status.ok()) << status.message();
  return model;
}

std::vector<std::string> RelativeFiles(const std::string& root) {
  std::vector<std::string> files;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(root, error); it != fs::end(it); ++it) {
    if (it->is_regular_file()) files.push_back(fs::relative(it->path(), root).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(BenchmarkAssetsTest, RegeneratingGivesTheCommittedFilesByteForByte) {
  const std::string out = ::testing::TempDir() + "/edgefit_assets_" + std::to_string(::getpid());
  const Status status = GenerateBenchmarkAssets(out);
  ASSERT_TRUE(status.ok()) << status.message();
  for (const std::string model : {"robot", "conveyor"}) {
    const std::vector<std::string> committed = RelativeFiles(kAssets + "/" + model);
    ASSERT_EQ(RelativeFiles(out + "/" + model), committed) << model;
    EXPECT_GE(committed.size(), 4u);
    for (const std::string& file : committed) {
      std::string expected, actual;
      ASSERT_TRUE(ReadFileToString(kAssets + "/" + model + "/" + file, &expected).ok());
      ASSERT_TRUE(ReadFileToString(out + "/" + model + "/" + file, &actual).ok());
      EXPECT_TRUE(expected == actual) << model << "/" << file << " differs from the generator's";
    }
  }
  fs::remove_all(out);
}

TEST(BenchmarkAssetsTest, EveryMeshIsClosedWithManySharpEdges) {
  std::uintmax_t total_bytes = 0;
  int meshes = 0;
  for (const std::string model : {"robot", "conveyor"}) {
    for (const std::string& file : RelativeFiles(kAssets + "/" + model)) {
      const std::string path = kAssets + "/" + model + "/" + file;
      total_bytes += fs::file_size(path);
      if (fs::path(file).extension() != ".stl") continue;
      ++meshes;
      TriangleMesh mesh;
      ASSERT_TRUE(LoadMesh(path, Eigen::Vector3d::Ones(), &mesh).ok()) << path;
      WeldIdenticalVertices(&mesh);
      const MeshTopologyReport report = AnalyzeMeshTopology(mesh);
      EXPECT_TRUE(report.IsClosedAndOriented())
          << file << ": open " << report.open_edges << ", non-manifold "
          << report.non_manifold_edges << ", misoriented " << report.misoriented_edges
          << ", degenerate " << report.degenerate_triangles;
      EXPECT_GT(SignedVolume(mesh), 0.0) << file;
      EXPECT_LE(mesh.triangles.size(), 40000u) << file;
      const MeshEdges edges = ExtractSharpEdges(mesh);
      EXPECT_EQ(edges.boundary.size(), 0u) << file;
      EXPECT_GE(edges.sharp.size(), 100u) << file;
    }
  }
  EXPECT_EQ(meshes, 12 + 7);
  EXPECT_LT(total_bytes, 15u << 20);
}

TEST(RobotAssetTest, SixRevoluteMainJointsBalancerLoopAndTool0) {
  KinematicModel bare;
  const Status status = LoadKinematicModel(kRobotUrdf, {}, &bare);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(bare.IndependentJoints().size(), 6u);
  const KinematicModel model = LoadRobotWithGun();
  for (int k = 1; k <= 6; ++k) {
    const int j = model.JointIndex("joint_" + std::to_string(k));
    ASSERT_GE(j, 0);
    EXPECT_EQ(model.joints()[j].type, JointType::kRevolute);
    EXPECT_TRUE(model.joints()[j].IsIndependent());
    EXPECT_TRUE(model.joints()[j].has_limits);
  }
  EXPECT_GE(model.LinkIndex("tool0"), 0);
  EXPECT_GE(model.LinkIndex("tcp"), 0);
  ASSERT_EQ(model.loop_closures().size(), 1u);
  for (int j : model.loop_closures()[0].joints) EXPECT_FALSE(model.joints()[j].IsIndependent());
  // Independent: six main joints and the gun's electrode.
  EXPECT_EQ(model.IndependentJoints().size(), 7u);
}

TEST(RobotAssetTest, LoopClosureIsSolvedAcrossPosturesAndRandomJoints) {
  const KinematicModel model = LoadRobotWithGun();
  ASSERT_EQ(model.loop_closures().size(), 1u);
  const LoopClosure& closure = model.loop_closures()[0];
  std::vector<std::vector<double>> samples;
  for (const auto& [name, posture] : ReadPostures(kAssets + "/robot/postures.json")) {
    samples.push_back(PostureJoints(model, posture));
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<double> q = model.ZeroJoints();
    for (int j : model.IndependentJoints()) {
      const Joint& joint = model.joints()[j];
      q[j] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
    }
    const Status status = model.ResolveDependentJoints(&q, 1e-9);
    ASSERT_TRUE(status.ok()) << status.message();
    samples.push_back(q);
  }
  for (const std::vector<double>& q : samples) {
    EXPECT_LT(LoopClosureResidual(model, closure, q).norm(), 1e-9);
    for (int j : closure.joints) {
      EXPECT_GE(q[j], model.joints()[j].lower);
      EXPECT_LE(q[j], model.joints()[j].upper);
    }
  }
}

TEST(RobotAssetTest, PosturesInsideLimitsAboveTheFloorAndAbout2_5mTall) {
  const KinematicModel model = LoadRobotWithGun();
  const auto postures = ReadPostures(kAssets + "/robot/postures.json");
  ASSERT_EQ(postures.size(), 3u);
  std::vector<double> zero = model.ZeroJoints();
  ASSERT_TRUE(model.ResolveDependentJoints(&zero, 1e-9).ok());
  EXPECT_GE(model.BoundingBox(zero).min().z(), 0.0);
  std::set<std::string> independent;
  for (int j : model.IndependentJoints()) independent.insert(model.joints()[j].name);
  for (const auto& [name, posture] : postures) {
    std::set<std::string> listed;
    for (const auto& [joint, value] : posture) {
      listed.insert(joint);
      const Joint& limits = model.joints()[model.JointIndex(joint)];
      EXPECT_GE(value, limits.lower) << name << " " << joint;
      EXPECT_LE(value, limits.upper) << name << " " << joint;
    }
    EXPECT_EQ(listed, independent) << name;
    const Eigen::AlignedBox3d box = model.BoundingBox(PostureJoints(model, posture));
    EXPECT_GE(box.min().z(), 0.0) << name;
    if (name == "home") {
      EXPECT_NEAR(box.max().z(), 2.5, 0.4) << name;
    }
  }
}

TEST(RobotAssetTest, WeldGunIsAboutOneMetreLongWithOneMovingElectrode) {
  KinematicModel gun;
  ASSERT_TRUE(LoadKinematicModel(kGunUrdf, {}, &gun).ok());
  EXPECT_EQ(gun.IndependentJoints().size(), 1u);
  EXPECT_GE(gun.LinkIndex("tcp"), 0);
  const Eigen::AlignedBox3d box = gun.BoundingBox(gun.ZeroJoints());
  EXPECT_NEAR(box.sizes().maxCoeff(), 1.0, 0.25);
}

TEST(ConveyorAssetTest, BranchedChainOfPrismaticJoints) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(kConveyorUrdf, {}, &model).ok());
  int prismatic = 0;
  for (const Joint& joint : model.joints()) {
    if (joint.type == JointType::kPrismatic) {
      ++prismatic;
      EXPECT_TRUE(joint.has_limits && joint.IsIndependent()) << joint.name;
    }
  }
  EXPECT_GE(prismatic, 4);
  EXPECT_TRUE(model.loop_closures().empty());
  // A joint "moves something" when it or a joint below it is moving.
  std::function<bool(int)> moves = [&](int j) {
    if (model.joints()[j].IsMoving()) return true;
    for (int child : model.links()[model.joints()[j].child_link].child_joints) {
      if (moves(child)) return true;
    }
    return false;
  };
  int branching_links = 0;
  for (const Link& link : model.links()) {
    int moving_children = 0;
    for (int j : link.child_joints) moving_children += moves(j) ? 1 : 0;
    if (moving_children >= 2) ++branching_links;
  }
  EXPECT_GE(branching_links, 2);  // base_link (two carriages) and lifter_2 (two clamps)
}

TEST(ConveyorAssetTest, PosturesSizeAndSymmetricArmTips) {
  KinematicModel model;
  ASSERT_TRUE(LoadKinematicModel(kConveyorUrdf, {}, &model).ok());
  const auto postures = ReadPostures(kAssets + "/conveyor/postures.json");
  ASSERT_EQ(postures.size(), 3u);
  EXPECT_GE(model.BoundingBox(model.ZeroJoints()).min().z(), 0.0);
  for (const auto& [name, posture] : postures) {
    EXPECT_EQ(posture.size(), model.IndependentJoints().size()) << name;
    for (const auto& [joint, value] : posture) {
      const Joint& limits = model.joints()[model.JointIndex(joint)];
      EXPECT_GE(value, limits.lower) << name << " " << joint;
      EXPECT_LE(value, limits.upper) << name << " " << joint;
    }
    const std::vector<double> q = PostureJoints(model, posture);
    const Eigen::AlignedBox3d box = model.BoundingBox(q);
    EXPECT_GE(box.min().z(), 0.0) << name;
    EXPECT_NEAR(box.sizes().x(), 5.5, 0.3) << name;
    EXPECT_NEAR(box.sizes().y(), 1.6, 0.3) << name;
    EXPECT_NEAR(box.max().z(), 1.7, 0.3) << name;
    // Tips: mirror images about the long axis, and the highest point is a tip.
    const std::vector<Pose> T = model.ForwardKinematics(q);
    double highest_tip = 0.0;
    for (const std::string pair : {"tip_1", "tip_2"}) {
      const Eigen::Vector3d left = T[model.LinkIndex(pair + "_left")].translation();
      const Eigen::Vector3d right = T[model.LinkIndex(pair + "_right")].translation();
      EXPECT_NEAR(left.y(), -right.y(), 1e-9) << name;
      EXPECT_GT(left.y(), 0.3) << name;
      highest_tip = std::max({highest_tip, left.z(), right.z()});
    }
    EXPECT_NEAR(box.max().z(), highest_tip, 1e-6) << name;
  }
}

}  // namespace
}  // namespace edgefit
