// The real robot models in EDGEFIT_SHARED_DIR/robots (never copied into the
// repository); every test skips when that directory is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "edgefit/model/composition.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/sharp_edges.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/model/urdf_loader.h"
#include "model/calibrated_urdf_check.h"

namespace edgefit {
namespace {

const std::string kRobots = EDGEFIT_SHARED_DIR "/robots";

struct RobotCase {
  std::string name;        // Folder and URDF basename.
  bool floor_standing;     // Zero-pose z-min at the floor (z = 0).
  int total_triangles;     // Measured, all links.
  Eigen::Vector3d bb_min;  // Measured zero-pose bounding box [m], checked by eye.
  Eigen::Vector3d bb_max;
};

std::string UrdfPath(const std::string& name) {
  return kRobots + "/" + name + "/" + name + ".urdf";
}

class RobotModelTest : public ::testing::TestWithParam<RobotCase> {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(UrdfPath(GetParam().name))) {
      GTEST_SKIP() << UrdfPath(GetParam().name) << " absent";
    }
    const Status status = LoadKinematicModel(UrdfPath(GetParam().name), {}, &model_);
    ASSERT_TRUE(status.ok()) << status.message();
  }
  // Zero of the independent joints, dependent joints resolved.
  std::vector<double> ZeroPose() const {
    std::vector<double> q = model_.ZeroJoints();
    const Status status = model_.ResolveDependentJoints(&q);
    EXPECT_TRUE(status.ok()) << status.message();
    return q;
  }
  KinematicModel model_;
};

TEST_P(RobotModelTest, MeshesLoadAndEveryVisualLinkHasTriangles) {
  int total = 0;
  for (const Link& link : model_.links()) {
    int link_triangles = 0;
    for (const Visual& visual : link.visuals) {
      EXPECT_GT(visual.triangle_count, 0) << link.name << " " << visual.mesh_path;
      link_triangles += visual.triangle_count;
    }
    EXPECT_EQ(static_cast<int>(link.mesh.triangles.size()), link_triangles) << link.name;
    EXPECT_EQ(link.visuals.empty(), link.mesh.empty()) << link.name;
    const Eigen::AlignedBox3d bb = link.mesh.BoundingBox();
    std::cout << "  " << GetParam().name << " link " << link.name << ": " << link_triangles
              << " triangles";
    if (!bb.isEmpty())
      std::cout << ", area " << link.mesh.SurfaceArea() << " m2, bbox [" << bb.min().transpose()
                << "] [" << bb.max().transpose() << "]";
    std::cout << "\n";
    total += link_triangles;
  }
  std::cout << "  " << GetParam().name << " total triangles: " << total << "\n";
  EXPECT_EQ(total, GetParam().total_triangles);
}

TEST_P(RobotModelTest, JointOriginsLieNearTheirLinkMeshes) {
  // Generic check that meshes sit in their link frames (units, up axis,
  // visual origins): the origin of each joint whose child has a mesh lies
  // within 0.15 m of the parent mesh's box or of the child mesh's box (at
  // q = 0, in the parent frame). Bare frames (base, flange, tool0; FANUC's
  // "base" at the J2 height) carry no mesh and are not checked.
  for (const Joint& joint : model_.joints()) {
    const Link& parent = model_.links()[joint.parent_link];
    const Link& child = model_.links()[joint.child_link];
    if (child.mesh.empty()) continue;
    Eigen::AlignedBox3d parent_box = parent.mesh.BoundingBox();
    Eigen::AlignedBox3d child_box = child.mesh.BoundingBox(joint.T_parent_child(0.0));
    for (Eigen::AlignedBox3d* box : {&parent_box, &child_box}) {
      if (box->isEmpty()) continue;
      box->min().array() -= 0.15;
      box->max().array() += 0.15;
    }
    const Eigen::Vector3d origin = joint.T_parent_joint.translation();
    EXPECT_TRUE((!parent_box.isEmpty() && parent_box.contains(origin)) ||
                child_box.contains(origin))
        << GetParam().name << ": joint " << joint.name << " origin " << origin.transpose()
        << " far from the meshes of " << parent.name << " and " << child.name;
  }
}

TEST_P(RobotModelTest, SurfaceSamplesAndSharpEdges) {
  SamplingOptions options;  // 2 mm spacing.
  const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model_, options);
  size_t total = 0, expected = 0, sharp = 0, boundary = 0;
  for (size_t l = 0; l < model_.links().size(); ++l) {
    const TriangleMesh& mesh = model_.links()[l].mesh;
    if (mesh.empty()) continue;
    total += samples[l].size();
    expected +=
        static_cast<size_t>(std::llround(mesh.SurfaceArea() / (options.spacing * options.spacing)));
    const MeshEdges edges = ExtractSharpEdges(mesh);
    sharp += edges.sharp.size();
    boundary += edges.boundary.size();
    EXPECT_FALSE(edges.sharp.empty()) << model_.links()[l].name;
  }
  std::cout << "  " << GetParam().name << ": " << total << " samples at 2 mm, " << sharp
            << " sharp edges, " << boundary << " open boundary edges\n";
  EXPECT_NEAR(static_cast<double>(total), static_cast<double>(expected),
              1.0 * model_.links().size());
}

TEST_P(RobotModelTest, ZeroPoseBoundingBox) {
  const Eigen::AlignedBox3d bb = model_.BoundingBox(ZeroPose());
  std::cout << "  " << GetParam().name << " zero-pose bbox min [" << bb.min().transpose()
            << "] max [" << bb.max().transpose() << "] size [" << bb.sizes().transpose() << "]\n";
  if (GetParam().floor_standing) {
    EXPECT_NEAR(bb.min().z(), 0.0, 0.002);
  }
  EXPECT_LT((bb.min() - GetParam().bb_min).cwiseAbs().maxCoeff(), 0.005) << bb.min().transpose();
  EXPECT_LT((bb.max() - GetParam().bb_max).cwiseAbs().maxCoeff(), 0.005) << bb.max().transpose();
}

// Zero-pose boxes measured with this loader and checked against the data
// sheets (zero pose = arm forward, upper arm vertical):
//  - KUKA KR150 R3100: reach 3.1 m; x to 3.30 (flange face), top of link 3 1.11 m.
//  - ABB IRB 6700-200/2.60: x to 1.6625 = 0.32 + 1.1425 + 0.2 (J2 offset,
//    forearm, wrist to flange), top 2.28 m.
//  - FANUC M-900iB/700: J2 at 0.94 m, x to 1.995, top 2.56 m.
//  - KUKA KR150-2 on an 8.17 m rail along world y (rail mesh in mm, scaled),
//    robot facing +x, x to 3.14, top 1.93 m.
//  - Motoman MotoPos D500 positioner: 0.50 x 0.93 x 0.55 m.
//  - Weld gun X16005 (root = flange face): 0.82 x 0.31 x 0.50 m.
const RobotCase kRobotCases[] = {
    {"kuka_kr150r3100_2", true, 59721, {-0.7540, -0.4309, 0.0000}, {3.2997, 0.4309, 1.1060}},
    {"abb_irb6700_200_260", true, 66530, {-0.7600, -0.4560, 0.0000}, {1.6625, 0.3600, 2.2762}},
    {"fanuc_m900ib700", true, 4384, {-0.8120, -0.7258, 0.0000}, {1.9950, 0.7258, 2.5600}},
    {"kuka_kr150_2_on_linear_axis",
     true,
     52934,
     {-0.8790, -4.0829, 0.0000},
     {3.1420, 4.0829, 1.9350}},
    {"motoman_motopos_d500", true, 17117, {-0.2500, -0.5568, -0.0002}, {0.2500, 0.3782, 0.5452}},
    {"weld_gun_x16005_botrail", false, 6176, {-0.2580, -0.1530, 0.0000}, {0.5655, 0.1530, 0.4997}},
};

INSTANTIATE_TEST_SUITE_P(Robots, RobotModelTest, ::testing::ValuesIn(kRobotCases),
                         [](const ::testing::TestParamInfo<RobotCase>& info) {
                           return info.param.name;
                         });

// Loads one model by folder name; false (and a skip) when the data is absent.
bool LoadRobot(const std::string& name, KinematicModel* model) {
  if (!std::filesystem::exists(UrdfPath(name))) return false;
  const Status status = LoadKinematicModel(UrdfPath(name), {}, model);
  EXPECT_TRUE(status.ok()) << status.message();
  return status.ok();
}

TEST(RobotDetailTest, ColladaMeshesAreZUpAndMillimetreStlIsScaled) {
  KinematicModel model;
  if (!LoadRobot("kuka_kr150_2_on_linear_axis", &model)) GTEST_SKIP() << "robots absent";
  // KR 150-2 base (DAE, Z_UP, metres): a 0.33 m high plinth standing on z = 0,
  // symmetric in y. Read as Y-up it would span z = +-0.5.
  const Eigen::AlignedBox3d base =
      model.links()[model.LinkIndex("robot_base_link")].mesh.BoundingBox();
  EXPECT_NEAR(base.min().z(), 0.0, 1e-3);
  EXPECT_NEAR(base.max().z(), 0.331, 1e-3);
  EXPECT_NEAR(base.min().y(), -base.max().y(), 1e-3);
  // The rail STL is in millimetres with scale 0.001: 8.17 m long, 0.48 m high.
  const Eigen::AlignedBox3d rail =
      model.links()[model.LinkIndex("linear_axis_base_link")].mesh.BoundingBox();
  EXPECT_NEAR(rail.sizes().x(), 8.166, 1e-3);
  EXPECT_NEAR(rail.sizes().z(), 0.483, 1e-3);
  // The prismatic joint moves the robot 5.4 m along the rail (world y).
  std::vector<double> q = model.ZeroJoints();
  const int track = model.JointIndex("linear_axis_actuation_joint");
  const int robot = model.LinkIndex("robot_base_link");
  const Eigen::Vector3d p0 = model.ForwardKinematics(q)[robot].translation();
  q[track] = 5.4;
  const Eigen::Vector3d p1 = model.ForwardKinematics(q)[robot].translation();
  EXPECT_TRUE((p1 - p0).isApprox(Eigen::Vector3d(0, 5.4, 0), 1e-9)) << (p1 - p0).transpose();
}

TEST(RobotDetailTest, AbbBalancerMimicJoints) {
  KinematicModel model;
  if (!LoadRobot("abb_irb6700_200_260", &model)) GTEST_SKIP() << "robots absent";
  std::vector<double> q = model.ZeroJoints();
  q[model.JointIndex("joint_2")] = 0.4;
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  EXPECT_DOUBLE_EQ(q[model.JointIndex("cylinder_joint")], -0.1);
  EXPECT_DOUBLE_EQ(q[model.JointIndex("piston_joint")], 0.06);
  EXPECT_EQ(model.joints()[model.JointIndex("piston_joint")].type, JointType::kPrismatic);
  EXPECT_EQ(model.IndependentJoints().size(), 6u);
}

TEST(RobotDetailTest, FanucParallelogramMimicJoints) {
  KinematicModel model;
  if (!LoadRobot("fanuc_m900ib700", &model)) GTEST_SKIP() << "robots absent";
  std::vector<double> q = model.ZeroJoints();
  q[model.JointIndex("joint_2")] = 0.2;
  q[model.JointIndex("joint_3")] = -0.3;
  ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
  EXPECT_DOUBLE_EQ(q[model.JointIndex("pjoint_1")], 0.3);
  EXPECT_DOUBLE_EQ(q[model.JointIndex("pjoint_2")], -0.3);
  EXPECT_DOUBLE_EQ(q[model.JointIndex("balancer_left_joint")], 0.18 * 0.2);
  EXPECT_DOUBLE_EQ(q[model.JointIndex("piston_right_joint")], 1.18 * 0.2);
  EXPECT_EQ(model.joints()[model.JointIndex("pjoint_1")].type, JointType::kContinuous);
  EXPECT_EQ(model.IndependentJoints().size(), 6u);
}

TEST(RobotDetailTest, WeldGunAttachedAtKukaTool0MovesWithJointA6) {
  KinematicModel model;
  if (!LoadRobot("kuka_kr150r3100_2", &model)) GTEST_SKIP() << "robots absent";
  AttachSpec spec;
  ASSERT_TRUE(ParseAttachSpec(UrdfPath("weld_gun_x16005_botrail") + "@tool0", &spec).ok());
  const Status status = AttachModel(spec, {}, &model);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_GE(model.JointIndex("tool0_to_mount"), 0);
  EXPECT_EQ(model.links()[model.LinkIndex("body")].source, spec.path);
  EXPECT_EQ(model.IndependentJoints().size(), 7u);  // 6 axes + the gun's electrode.
  const int tool0 = model.LinkIndex("tool0"), mount = model.LinkIndex("mount"),
            tcp = model.LinkIndex("tcp");
  std::vector<double> q = model.ZeroJoints();
  const std::vector<Pose> T0 = model.ForwardKinematics(q);
  q[model.JointIndex("joint_a6")] = 1.0;
  const std::vector<Pose> T1 = model.ForwardKinematics(q);
  EXPECT_TRUE(T1[mount].isApprox(T1[tool0], 1e-12));
  EXPECT_TRUE((T0[tool0].inverse() * T0[tcp]).isApprox(T1[tool0].inverse() * T1[tcp], 1e-12));
  EXPECT_GT((T1[tcp].translation() - T0[tcp].translation()).norm(), 0.1);  // TCP off the a6 axis.
  // The gun extends the zero-pose box beyond the bare robot's 3.30 m.
  EXPECT_GT(model.BoundingBox(model.ZeroJoints()).max().x(), 3.3);
}

// `edgefit fit --out_urdf` for each arm carrying the shared gun: the file
// loads back from another directory (mesh paths made absolute, mimic joints
// kept) with every link, the gun's included, at the fitted pose.
TEST(RobotDetailTest, CalibratedUrdfWithTheGunLoadsBack) {
  for (const char* name : {"kuka_kr150r3100_2", "abb_irb6700_200_260", "fanuc_m900ib700"}) {
    KinematicModel model;
    if (!LoadRobot(name, &model)) GTEST_SKIP() << "robots absent";
    std::vector<AttachSpec> specs(1);
    ASSERT_TRUE(ParseAttachSpec(UrdfPath("weld_gun_x16005_botrail") + "@tool0", &specs[0]).ok());
    ASSERT_TRUE(AttachModel(specs[0], {}, &model).ok());
    std::vector<double> q = model.ZeroJoints();
    for (const int j : model.IndependentJoints()) {
      const Joint& joint = model.joints()[static_cast<size_t>(j)];
      q[static_cast<size_t>(j)] = joint.has_limits ? 0.3 * joint.lower + 0.7 * joint.upper : 0.5;
    }
    ASSERT_TRUE(model.ResolveDependentJoints(&q).ok()) << name;
    SCOPED_TRACE(name);
    testing_util::ExpectCalibratedUrdfLoadsBack(UrdfPath(name), specs, model, q,
                                                PoseFromXyzRpy({-0.7, 2.1, 0.0}, {0, 0, -1.2}),
                                                std::string("calibrated_") + name);
  }
}

}  // namespace
}  // namespace edgefit
