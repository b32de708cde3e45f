// Which joints the geometry can pin (solvers/joints/observability.h): a
// round flange turned about its axis stays on its own surface, a flange
// carrying a tool does not; and the whole turns of a joint whose range
// exceeds one.
#include "solvers/joints/observability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "edgefit/model/composition.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

constexpr double kSpacing = 0.004;  // [m], the fit's ICP samples

SurfaceSamples MeshSamples(const TriangleMesh& mesh) { return SampleMeshSurface(mesh, kSpacing, 7); }

double LargestOffShare(const SurfaceSamples& samples, const Eigen::Vector3d& axis) {
  const ObservabilityOptions options;
  double largest = 0.0;
  for (const double turn : options.turns) {
    largest = std::max(largest, TurnedOffShare(samples, axis, turn, kSpacing, options));
  }
  return largest;
}

TEST(ObservabilityTest, RoundFlangeStaysOnItsSurfaceTurnedAboutItsAxisOnly) {
  const SurfaceSamples flange = MeshSamples(MakeCylinderMesh(0.08, 0.10, 64));
  EXPECT_LT(LargestOffShare(flange, Eigen::Vector3d::UnitZ()), 0.01);
  EXPECT_GT(LargestOffShare(flange, Eigen::Vector3d::UnitX()), 0.5);
  TriangleMesh with_tool = MakeCylinderMesh(0.08, 0.10, 64);
  with_tool.Append(MakeBoxMesh({0.20, 0.10, 0.10}), PoseFromXyzRpy({0.20, 0, 0.10}, {0, 0, 0}));
  const double off = LargestOffShare(MeshSamples(with_tool), Eigen::Vector3d::UnitZ());
  std::printf("  flange with a box beside it: %.2f of its samples off at most\n", off);
  EXPECT_GT(off, 0.5);
}

// The bundled robot: its bare flange cannot be pinned by any scan, the
// same flange carrying the gun can; no other joint is unobservable.
TEST(ObservabilityTest, BareFlangeOfTheBundledRobotIsUnobservable) {
  const std::string dir = std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/";
  for (const bool gun : {false, true}) {
    KinematicModel model;
    std::vector<AttachSpec> specs(gun ? 1 : 0);
    if (gun) {
      ASSERT_TRUE(ParseAttachSpec(dir + "weld_gun.urdf@tool0", &specs[0]).ok());
    }
    ASSERT_TRUE(
        LoadModelWithAttachments(dir + "robot.urdf", specs, ModelLoadOptions(), &model).ok());
    SamplingOptions sampling;
    sampling.spacing = kSpacing;
    const std::vector<SurfaceSamples> samples = SampleModelSurfaces(model, sampling);
    for (size_t j = 0; j < model.joints().size(); ++j) {
      const Joint& joint = model.joints()[j];
      if (!joint.IsIndependent()) continue;
      double off = 0.0;
      const bool unobservable = TurnIsUnobservable(model, static_cast<int>(j), model.ZeroJoints(),
                                                   samples, kSpacing, ObservabilityOptions(), &off);
      std::printf("  %s %s: %.3f of its subtree's samples off at most\n",
                  gun ? "with the gun" : "bare", joint.name.c_str(), off);
      EXPECT_EQ(unobservable, !gun && joint.name == "joint_6") << joint.name;
    }
  }
}

// The bundled robot's square base looks the same every quarter turn about
// joint_1, the balancer arm's too; the KUKA's (../shared) at no turn. The
// base turned for another joint_1 value leaves link_1 where it was.
TEST(ObservabilityTest, BaseSymmetryOfSquareBasesAndNotOfTheKuka) {
  const std::string source = std::string(EDGEFIT_SOURCE_DIR) + "/assets/";
  const std::string kuka = std::string(EDGEFIT_SHARED_DIR) + "/robots/kuka_kr150r3100_2/kuka_kr150r3100_2.urdf";
  for (const std::string& urdf : {source + "robot/robot.urdf", source + "models/balancer_arm.urdf", kuka}) {
    if (urdf == kuka && !std::ifstream(kuka).good()) continue;
    KinematicModel model;
    ASSERT_TRUE(LoadModelWithAttachments(urdf, {}, ModelLoadOptions(), &model).ok()) << urdf;
    SamplingOptions sampling;
    sampling.spacing = kSpacing;
    const BaseSymmetry symmetry =
        FindBaseSymmetry(model, SampleModelSurfaces(model, sampling), kSpacing, ObservabilityOptions());
    if (urdf == kuka) {
      EXPECT_EQ(symmetry.joint, -1);
      EXPECT_TRUE(symmetry.turns.empty());
      continue;
    }
    ASSERT_EQ(symmetry.joint, model.JointIndex("joint_1")) << urdf;
    ASSERT_EQ(symmetry.turns.size(), 3u) << urdf;
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(symmetry.turns[k], (k + 1) * M_PI / 2, 1e-12);
    std::vector<double> q = model.ZeroJoints();
    q[static_cast<size_t>(symmetry.joint)] = 0.3;
    ASSERT_TRUE(model.ResolveDependentJoints(&q).ok());
    const Pose T = PoseFromXyYaw(1.0, 2.0, 0.4);
    std::vector<double> q_turned = q;
    q_turned[static_cast<size_t>(symmetry.joint)] = 0.3 - M_PI / 2;
    ASSERT_TRUE(model.ResolveDependentJoints(&q_turned).ok());
    const Pose T_turned = TurnBaseForJoint(model, symmetry.joint, T, 0.3, 0.3 - M_PI / 2);
    const int link_1 = model.joints()[static_cast<size_t>(symmetry.joint)].child_link;
    EXPECT_TRUE(model.ForwardKinematics(q, T)[static_cast<size_t>(link_1)].matrix().isApprox(
        model.ForwardKinematics(q_turned, T_turned)[static_cast<size_t>(link_1)].matrix(), 1e-12));
    EXPECT_NEAR(std::abs(std::remainder(RpyFromRotation(T_turned.linear()).z() - 0.4, 2 * M_PI)), M_PI / 2, 1e-9);
  }
}

// A cobot's round base (a cylinder about its first joint's axis) looks
// the same at any turn: round, so its first joint is reported at zero and
// unobservable; the bundled robot's square plate only every quarter turn.
TEST(ObservabilityTest, ARoundBaseIsRoundASquareOneIsNot) {
  const std::string dir = ::testing::TempDir();
  const std::string urdf = dir + "/round_base.urdf";
  std::ofstream(urdf) << R"(<robot name="round">
  <link name="base"><visual><geometry><cylinder radius="0.12" length="0.15"/></geometry>
    <origin xyz="0 0 0.075"/></visual></link>
  <link name="arm"><visual><geometry><box size="0.1 0.1 0.5"/></geometry>
    <origin xyz="0.05 0 0.25"/></visual></link>
  <joint name="joint_1" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.15"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint></robot>)";
  for (const auto& [path, round] : {std::make_pair(urdf, true),
                                    std::make_pair(std::string(EDGEFIT_SOURCE_DIR) +
                                                       "/assets/robot/robot.urdf",
                                                   false)}) {
    KinematicModel model;
    ASSERT_TRUE(LoadModelWithAttachments(path, {}, ModelLoadOptions(), &model).ok()) << path;
    SamplingOptions sampling;
    sampling.spacing = kSpacing;
    const BaseSymmetry symmetry = FindBaseSymmetry(model, SampleModelSurfaces(model, sampling),
                                                   kSpacing, ObservabilityOptions());
    ASSERT_EQ(symmetry.joint, model.JointIndex("joint_1")) << path;
    EXPECT_EQ(symmetry.round, round) << path;
  }
}

TEST(ObservabilityTest, WholeTurnsOfAJointBeyondAFullTurn) {
  Joint a4;  // a KUKA axis 4: +-350 deg
  a4.type = JointType::kRevolute;
  a4.has_limits = true;
  a4.lower = -350.0 * M_PI / 180.0;
  a4.upper = 350.0 * M_PI / 180.0;
  const std::vector<double> turns = WholeTurns(a4, 3.3966);
  ASSERT_EQ(turns.size(), 2u);
  EXPECT_NEAR(turns[0], 3.3966 - 2.0 * M_PI, 1e-12);
  EXPECT_NEAR(turns[1], 3.3966, 1e-12);
  EXPECT_NEAR(NearestZeroTurn(a4, 3.3966), 3.3966 - 2.0 * M_PI, 1e-12);
  EXPECT_NEAR(NearestZeroTurn(a4, -0.5), -0.5, 1e-12);
  EXPECT_EQ(WholeTurns(a4, 0.1).size(), 1u);  // within 10 deg of zero: a turn away is beyond
  EXPECT_EQ(WholeTurns(a4, 6.0).size(), 2u);  // 344 deg and -16 deg
  Joint a1 = a4;                              // +-170 deg: one value
  a1.lower = -170.0 * M_PI / 180.0;
  a1.upper = 170.0 * M_PI / 180.0;
  EXPECT_EQ(WholeTurns(a1, 2.0), std::vector<double>{2.0});
  Joint wheel;  // continuous: no limits to count turns within
  wheel.type = JointType::kContinuous;
  EXPECT_EQ(WholeTurns(wheel, 7.0), std::vector<double>{7.0});
  EXPECT_NEAR(NearestZeroTurn(wheel, 7.0), 7.0 - 2.0 * M_PI, 1e-12);
}

}  // namespace
}  // namespace edgefit
