// The planning world of a fitted machine (edgefit/world/planning_world.h):
// cell.urdf loaded again at joint_states.yaml's values, and cell_frozen.urdf
// at its zero, place every link where the fitted model is; cell.srdf's
// as_scanned holds the fitted values; check_urdf accepts both URDFs; the
// folder is replaced whole, and left as it was when a write fails. The
// background's voxels: a closed surface around every point, and the same
// cells occupied in the OctoMap tree.
#include <gtest/gtest.h>
#include <unistd.h>
#include <octomap/OcTree.h>
#include <tinyxml2.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "edgefit/io/joint_states.h"
#include "edgefit/io/scan_io.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/world/planning_world.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

class PlanningWorldTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test and process: ctest runs this fixture's tests in
    // parallel, and one's TearDown must not remove another's world.
    dir_ = fs::temp_directory_path() /
           ("edgefit_planning_world_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    AttachSpec gun;
    gun.path = std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/weld_gun.urdf";
    gun.parent_link = "tool0";
    ASSERT_TRUE(LoadModelWithAttachments(std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/robot.urdf",
                                         {gun}, ModelLoadOptions(), &model_)
                    .ok());
    machine_.name = "robot_left";
    machine_.model = &model_;
    machine_.T_world_base = PoseFromXyzRpy(Eigen::Vector3d(2.0, -1.0, 0.05), Eigen::Vector3d(0.01, -0.02, 0.7));
    machine_.q = model_.ZeroJoints();
    int k = 0;
    for (size_t j = 0; j < model_.joints().size(); ++j) {
      const Joint& joint = model_.joints()[j];
      if (!joint.IsIndependent()) continue;
      const double t = 0.2 + 0.15 * (k++ % 5);  // inside every range
      machine_.q[j] = joint.has_limits ? joint.lower + t * (joint.upper - joint.lower) : t;
    }
    ASSERT_TRUE(model_.ResolveDependentJoints(&machine_.q).ok());
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Every link of the fitted model against the link of `cell` named
  // "robot_left_<link>", posed by q_cell from the cell's world.
  void ExpectSamePlaces(const KinematicModel& cell, const std::vector<double>& q_cell) {
    const std::vector<Pose> fitted = model_.ForwardKinematics(machine_.q, machine_.T_world_base);
    const std::vector<Pose> placed = cell.ForwardKinematics(q_cell, Pose::Identity());
    for (size_t l = 0; l < model_.links().size(); ++l) {
      const int c = cell.LinkIndex("robot_left_" + model_.links()[l].name);
      ASSERT_GE(c, 0) << model_.links()[l].name;
      EXPECT_LT((placed[static_cast<size_t>(c)].matrix() - fitted[l].matrix()).cwiseAbs().maxCoeff(), 1e-6)
          << model_.links()[l].name;
      const auto box = [](const TriangleMesh& mesh, const Pose& T) { return mesh.BoundingBox(T); };
      if (model_.links()[l].mesh.empty()) continue;
      const Eigen::AlignedBox3d a = box(model_.links()[l].mesh, fitted[l]);
      const Eigen::AlignedBox3d b = box(cell.links()[static_cast<size_t>(c)].mesh, placed[static_cast<size_t>(c)]);
      EXPECT_LT((a.min() - b.min()).norm() + (a.max() - b.max()).norm(), 1e-5) << model_.links()[l].name;
    }
  }

  fs::path dir_;
  KinematicModel model_;
  WorldMachine machine_;
};

TEST_F(PlanningWorldTest, PlacesEveryLinkWhereTheFitDid) {
  const fs::path world = dir_ / "world";
  std::vector<std::string> written;
  const Status status = WritePlanningWorld({machine_}, nullptr, BackgroundOptions(), world.string(), &written);
  ASSERT_TRUE(status.ok()) << status.message();
  for (const std::string& file : written) EXPECT_TRUE(fs::exists(file)) << file;
  for (const char* file : {"cell.urdf", "cell_frozen.urdf", "cell.srdf", "joint_states.yaml",
                           "machines_as_scanned.ply"}) {
    EXPECT_TRUE(fs::exists(world / file)) << file;
  }

  // cell.urdf at the values of joint_states.yaml.
  KinematicModel cell;
  ASSERT_TRUE(LoadKinematicModel((world / "cell.urdf").string(), ModelLoadOptions(), &cell).ok());
  EXPECT_EQ(cell.links()[static_cast<size_t>(cell.root_link())].name, "world");
  std::vector<std::pair<std::string, double>> states;
  ASSERT_TRUE(ReadJointStates((world / "joint_states.yaml").string(), &states).ok());
  std::vector<double> q_cell = cell.ZeroJoints();
  for (const auto& [name, value] : states) {
    const int j = cell.JointIndex(name);
    ASSERT_GE(j, 0) << name;
    q_cell[static_cast<size_t>(j)] = value;
  }
  ExpectSamePlaces(cell, q_cell);
  // Limits, effort and velocity as the machine's URDF gives them.
  for (const Joint& joint : model_.joints()) {
    const Joint& copy = cell.joints()[static_cast<size_t>(cell.JointIndex("robot_left_" + joint.name))];
    EXPECT_EQ(copy.type, joint.type) << joint.name;
    EXPECT_NEAR(copy.lower, joint.lower, 1e-8) << joint.name;
    EXPECT_NEAR(copy.upper, joint.upper, 1e-8) << joint.name;
    EXPECT_NEAR(copy.velocity, joint.velocity, 1e-8) << joint.name;
  }

  // cell_frozen.urdf: nothing moves, every link where the fit put it.
  KinematicModel frozen;
  ASSERT_TRUE(LoadKinematicModel((world / "cell_frozen.urdf").string(), ModelLoadOptions(), &frozen).ok());
  EXPECT_TRUE(frozen.IndependentJoints().empty());
  ExpectSamePlaces(frozen, frozen.ZeroJoints());

  // cell.srdf: the group and its as_scanned state.
  tinyxml2::XMLDocument srdf;
  ASSERT_EQ(srdf.LoadFile((world / "cell.srdf").string().c_str()), tinyxml2::XML_SUCCESS);
  std::map<std::string, double> as_scanned;
  for (auto* state = srdf.RootElement()->FirstChildElement("group_state"); state != nullptr;
       state = state->NextSiblingElement("group_state")) {
    EXPECT_STREQ(state->Attribute("name"), "as_scanned");
    EXPECT_STREQ(state->Attribute("group"), "robot_left");
    for (auto* j = state->FirstChildElement("joint"); j != nullptr; j = j->NextSiblingElement("joint")) {
      as_scanned[j->Attribute("name")] = j->DoubleAttribute("value");
    }
  }
  for (const int j : model_.IndependentJoints()) {
    const std::string name = "robot_left_" + model_.joints()[static_cast<size_t>(j)].name;
    ASSERT_EQ(as_scanned.count(name), 1u) << name;
    EXPECT_NEAR(as_scanned[name], machine_.q[static_cast<size_t>(j)], 1e-8) << name;
  }

  // machines_as_scanned.ply: the posed meshes, world frame.
  ScanSet ply;
  ASSERT_TRUE(ReadScans((world / "machines_as_scanned.ply").string(), ReadOptions(), &ply).ok());
  Eigen::AlignedBox3d expected;
  expected.setEmpty();
  const std::vector<Pose> fitted = model_.ForwardKinematics(machine_.q, machine_.T_world_base);
  for (size_t l = 0; l < model_.links().size(); ++l) expected.extend(model_.links()[l].mesh.BoundingBox(fitted[l]));
  Eigen::AlignedBox3d read;
  read.setEmpty();
  for (size_t i = 0; i < ply.scans[0].size(); ++i) read.extend(ply.scans[0].PointWorld(i));
  EXPECT_LT((expected.min() - read.min()).norm() + (expected.max() - read.max()).norm(), 1e-4);

  // check_urdf (liburdfdom-tools, installed by scripts/install-deps.sh) accepts both.
  if (std::system("command -v check_urdf > /dev/null 2>&1") == 0) {
    for (const char* file : {"cell.urdf", "cell_frozen.urdf"}) {
      const std::string command = "check_urdf " + (world / file).string() + " > /dev/null 2>&1";
      EXPECT_EQ(std::system(command.c_str()), 0) << file;
    }
  } else {
    std::printf("check_urdf not installed: not run\n");
  }
}

// What rides on a link off its CAD is a second collision of that link:
// loaded as collision geometry, the link holds both; as visual, its CAD.
TEST_F(PlanningWorldTest, AttachedGeometryIsASecondCollisionOfItsLink) {
  const int link_3 = model_.LinkIndex("link_3");
  ASSERT_GE(link_3, 0);
  machine_.attached.assign(model_.links().size(), TriangleMesh());
  machine_.attached[static_cast<size_t>(link_3)] = MakeBoxMesh(Eigen::Vector3d(0.1, 0.2, 0.3));
  const fs::path world = dir_ / "world";
  ASSERT_TRUE(WritePlanningWorld({machine_}, nullptr, BackgroundOptions(), world.string(), nullptr).ok());
  EXPECT_TRUE(fs::exists(world / "meshes/robot_left_link_3_attached.stl"));
  ModelLoadOptions as_collision;
  as_collision.collision_geometry = true;
  KinematicModel visual, collision;
  ASSERT_TRUE(LoadKinematicModel((world / "cell.urdf").string(), ModelLoadOptions(), &visual).ok());
  ASSERT_TRUE(LoadKinematicModel((world / "cell.urdf").string(), as_collision, &collision).ok());
  const int l = visual.LinkIndex("robot_left_link_3");
  const size_t cad = model_.links()[static_cast<size_t>(link_3)].mesh.triangles.size();
  EXPECT_EQ(visual.links()[static_cast<size_t>(l)].mesh.triangles.size(), cad);
  EXPECT_EQ(collision.links()[static_cast<size_t>(l)].mesh.triangles.size(), cad + 12);
  const int l2 = visual.LinkIndex("robot_left_link_2");
  EXPECT_EQ(collision.links()[static_cast<size_t>(l2)].mesh.triangles.size(),
            visual.links()[static_cast<size_t>(l2)].mesh.triangles.size());
  // The wrong number of attached meshes: one line, nothing written.
  machine_.attached.resize(2);
  EXPECT_NE(WritePlanningWorld({machine_}, nullptr, BackgroundOptions(), (dir_ / "other").string(), nullptr)
                .message()
                .find("attached meshes for 2 links"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "other"));
}

TEST_F(PlanningWorldTest, ReplacesTheFolderWholeOrLeavesIt) {
  const fs::path world = dir_ / "world";
  ASSERT_TRUE(WritePlanningWorld({machine_}, nullptr, BackgroundOptions(), world.string(), nullptr).ok());
  std::vector<std::pair<std::string, double>> before;
  ASSERT_TRUE(ReadJointStates((world / "joint_states.yaml").string(), &before).ok());

  WorldMachine bad = machine_;
  bad.q.pop_back();  // one value short
  WorldMachine slash = machine_;
  slash.name = "robot/left";
  WorldMachine twice = machine_;
  for (const std::vector<WorldMachine>& machines :
       {std::vector<WorldMachine>{bad}, std::vector<WorldMachine>{slash},
        std::vector<WorldMachine>{machine_, twice}, std::vector<WorldMachine>{}}) {
    const Status status = WritePlanningWorld(machines, nullptr, BackgroundOptions(), world.string(), nullptr);
    EXPECT_FALSE(status.ok());
    EXPECT_EQ(status.message().find('\n'), std::string::npos) << status.message();
  }
  std::vector<std::pair<std::string, double>> after;
  ASSERT_TRUE(ReadJointStates((world / "joint_states.yaml").string(), &after).ok());
  EXPECT_EQ(before, after);

  WorldMachine moved = machine_;
  moved.q[static_cast<size_t>(model_.IndependentJoints().front())] += 0.1;
  ASSERT_TRUE(WritePlanningWorld({moved}, nullptr, BackgroundOptions(), world.string(), nullptr).ok());
  ASSERT_TRUE(ReadJointStates((world / "joint_states.yaml").string(), &after).ok());
  EXPECT_NE(before, after);
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename(), "world") << "left behind: " << entry.path();
  }
}

// Every edge of a closed surface bounds faces in pairs.
void ExpectClosed(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;  // undirected edge -> faces
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
      ++directed[{a, b}];
    }
  }
  for (const auto& [edge, faces] : edges) EXPECT_EQ(faces % 2, 0) << edge.first << " " << edge.second;
  // Oriented: each edge is walked as often one way as the other.
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    ASSERT_NE(reverse, directed.end());
    EXPECT_EQ(reverse->second, count);
  }
}

TEST(BackgroundVoxelsTest, OneVoxelTwoVoxelsAndAnOutwardSurface) {
  const double v = 0.02;
  EXPECT_EQ(VoxelUnionSurface(OccupiedVoxels({Eigen::Vector3f(0.011f, 0.001f, -0.001f)}, v), v)
                .triangles.size(),
            12u);
  const std::vector<Eigen::Vector3f> pair = {Eigen::Vector3f(0.001f, 0.001f, 0.001f),
                                             Eigen::Vector3f(0.005f, 0.002f, 0.003f),
                                             Eigen::Vector3f(0.021f, 0.001f, 0.001f)};
  EXPECT_EQ(OccupiedVoxels(pair, v).size(), 2u);
  const TriangleMesh two = VoxelUnionSurface(OccupiedVoxels(pair, v), v);
  EXPECT_EQ(two.triangles.size(), 20u);  // 10 outer faces
  ExpectClosed(two);
  // Outward: the signed volume is the voxels' (divergence theorem).
  double volume = 0.0;
  for (const Eigen::Vector3i& t : two.triangles) {
    volume += two.vertices[t[0]].dot(two.vertices[t[1]].cross(two.vertices[t[2]])) / 6.0;
  }
  EXPECT_NEAR(volume, 2 * v * v * v, 1e-12);
}

// The merged rectangles are the same surface: the same area and enclosed
// volume, every face centre of the closed surface on them, and a slab's
// faces merged to its six sides.
TEST(BackgroundVoxelsTest, RectanglesAreTheSameSurface) {
  const double v = 0.02;
  std::vector<Eigen::Vector3f> points;
  for (int x = 0; x < 30; ++x) {
    for (int y = 0; y < 20; ++y) points.emplace_back((x + 0.5f) * v, (y + 0.5f) * v, 0.5f * v);  // a slab
  }
  for (int z = 1; z < 6; ++z) points.emplace_back(0.5f * v, 0.5f * v, (z + 0.5f) * v);          // a post on it
  points.emplace_back(10.5f * v, 5.5f * v, 3.5f * v);                                            // a voxel apart
  const std::vector<std::array<int32_t, 3>> voxels = OccupiedVoxels(points, v);
  const TriangleMesh closed = VoxelUnionSurface(voxels, v);
  const TriangleMesh merged = VoxelUnionRectangles(voxels, v);
  EXPECT_LT(merged.triangles.size() * 10, closed.triangles.size());
  const auto volume = [](const TriangleMesh& m) {
    double sum = 0.0;
    for (const Eigen::Vector3i& t : m.triangles) {
      sum += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
    }
    return sum;
  };
  EXPECT_NEAR(merged.SurfaceArea(), closed.SurfaceArea(), 1e-9);
  EXPECT_NEAR(volume(merged), volume(closed), 1e-12);
  EXPECT_NEAR(volume(merged), static_cast<double>(voxels.size()) * v * v * v, 1e-12);
  // Each closed face's centre lies in a rectangle of the same plane.
  for (size_t f = 0; f < closed.triangles.size(); f += 2) {
    const Eigen::Vector3i& t = closed.triangles[f];
    const Eigen::Vector3d centre = 0.5 * (closed.vertices[t[1]] + closed.vertices[t[2]]);
    bool on = false;
    for (const Eigen::Vector3i& r : merged.triangles) {
      const Eigen::Vector3d &a = merged.vertices[r[0]], &b = merged.vertices[r[1]], &c = merged.vertices[r[2]];
      const Eigen::Vector3d n = (b - a).cross(c - a);
      if (std::abs(n.normalized().dot(centre - a)) > 1e-12) continue;
      const double s1 = n.dot((b - a).cross(centre - a)), s2 = n.dot((c - b).cross(centre - b)),
                   s3 = n.dot((a - c).cross(centre - c));
      if (s1 >= -1e-15 && s2 >= -1e-15 && s3 >= -1e-15) on = true;
    }
    EXPECT_TRUE(on) << centre.transpose();
  }
}

TEST(BackgroundVoxelsTest, SurfaceAndOctreeHoldEveryPoint) {
  // A wall and a box's faces, scanned every 7 mm, and a point far off.
  std::vector<Eigen::Vector3f> points;
  for (double a = -0.5; a <= 0.5; a += 0.007) {
    for (double b = 0.0; b <= 0.6; b += 0.007) points.emplace_back(2.0f, a, b);
  }
  for (double a = 0.0; a <= 0.3; a += 0.007) {
    for (double b = 0.0; b <= 0.2; b += 0.007) {
      points.emplace_back(a + 0.5, b - 0.1, 0.25);
      points.emplace_back(a + 0.5, -0.1, b + 0.05);
    }
  }
  const fs::path dir = fs::temp_directory_path() / "edgefit_background_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  BackgroundOptions options;
  options.scene_tile = 10;  // 0.2 m tiles: several objects
  std::vector<std::string> names;
  ASSERT_TRUE(WriteBackground(OccupiedVoxels(points, options.voxel), options, dir.string(), &names).ok());
  EXPECT_EQ(names, (std::vector<std::string>{"background.ply", "background.scene", "background.bt"}));
  const TriangleMesh surface = VoxelUnionSurface(OccupiedVoxels(points, options.voxel), options.voxel);
  ExpectClosed(surface);
  octomap::OcTree tree((dir / "background.bt").string());
  EXPECT_DOUBLE_EQ(tree.getResolution(), options.voxel);
  for (const Eigen::Vector3f& p : points) {
    const octomap::OcTreeNode* node = tree.search(p.x(), p.y(), p.z());
    ASSERT_NE(node, nullptr) << p.transpose();
    EXPECT_TRUE(tree.isNodeOccupied(node)) << p.transpose();
  }
  EXPECT_EQ(tree.search(1.0, 0.5, 1.0), nullptr);  // never seen: unknown
  // The PLY holds the surface: its bounds are the voxels' around the points.
  ScanSet ply;
  ASSERT_TRUE(ReadScans((dir / "background.ply").string(), ReadOptions(), &ply).ok());
  Eigen::AlignedBox3d read, around;
  read.setEmpty();
  around.setEmpty();
  for (size_t i = 0; i < ply.scans[0].size(); ++i) read.extend(ply.scans[0].PointWorld(i));
  for (const Eigen::Vector3f& p : points) around.extend(p.cast<double>());
  EXPECT_TRUE(read.contains(around));
  EXPECT_LT((read.sizes() - around.sizes()).maxCoeff(), 2 * options.voxel + 1e-9);

  // background.scene as MoveIt's reader takes it: objects of one mesh each
  // at the origin, every one closed, together the same voxels' faces less
  // the tiles' shared ones.
  std::ifstream scene(dir / "background.scene");
  std::string name, marker;
  ASSERT_TRUE(std::getline(scene, name));
  EXPECT_EQ(name, "edgefit_background");
  int objects = 0;
  size_t triangles = 0;
  Eigen::AlignedBox3d tiles;
  tiles.setEmpty();
  while (scene >> marker && marker == "*") {
    std::string id, kind;
    double pose[7], colour[4];
    int shapes = 0, subframes = 0;
    size_t v = 0, t = 0;
    scene >> id;
    for (double& x : pose) scene >> x;
    scene >> shapes >> kind >> v >> t;
    ASSERT_EQ(shapes, 1);
    ASSERT_EQ(kind, "mesh");
    TriangleMesh mesh;
    mesh.vertices.resize(v);
    mesh.triangles.resize(t);
    for (Eigen::Vector3d& p : mesh.vertices) scene >> p.x() >> p.y() >> p.z();
    for (Eigen::Vector3i& f : mesh.triangles) scene >> f[0] >> f[1] >> f[2];
    for (double& x : pose) scene >> x;
    for (double& x : colour) scene >> x;
    scene >> subframes;
    ASSERT_TRUE(scene.good()) << id;
    EXPECT_EQ(subframes, 0);
    ExpectClosed(mesh);
    tiles.extend(mesh.BoundingBox(Pose::Identity()));
    triangles += t;
    ++objects;
  }
  EXPECT_EQ(marker, ".");
  EXPECT_GT(objects, 4);
  EXPECT_GE(triangles, surface.triangles.size());
  EXPECT_TRUE(tiles.isApprox(surface.BoundingBox(Pose::Identity())));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace edgefit
