// The spot-welding robot and its welding gun as URDF + STL files, plus
// three postures (paper Fig. 4a and Sec. 7.3). Geometry: robot_link_meshes.cc,
// weld_gun_meshes.cc; layout: robot_layout.h, weld_gun_layout.h.
#include <cmath>

#include "asset_output.h"
#include "edgefit/assets/benchmark_assets.h"
#include "edgefit/assets/posture_file.h"
#include "edgefit/assets/urdf_writer.h"
#include "robot_layout.h"
#include "robot_link_meshes.h"
#include "weld_gun_layout.h"

namespace edgefit {
namespace {

using assets_internal::At;

const Eigen::Vector4d kRobotColour(0.95, 0.55, 0.05, 1.0);
const Eigen::Vector4d kBalancerColour(0.3, 0.3, 0.32, 1.0);
const Eigen::Vector4d kGunColour(0.8, 0.12, 0.1, 1.0);

UrdfJointSpec Revolute(const std::string& name, const std::string& parent, const std::string& child,
                       const Pose& origin, const Eigen::Vector3d& axis, double lower, double upper) {
  UrdfJointSpec j;
  j.name = name;
  j.type = JointType::kRevolute;
  j.parent = parent;
  j.child = child;
  j.T_parent_joint = origin;
  j.axis = axis;
  j.lower = lower;
  j.upper = upper;
  j.velocity = 2.0;
  return j;
}

UrdfJointSpec Fixed(const std::string& name, const std::string& parent, const std::string& child,
                    const Pose& origin) {
  UrdfJointSpec j;
  j.name = name;
  j.parent = parent;
  j.child = child;
  j.T_parent_joint = origin;
  return j;
}

std::string RobotUrdf() {
  const assets_internal::RobotLayout& L = assets_internal::Layout();
  UrdfWriter urdf("spot_welding_robot",
                  "Six-axis 200 kg-class spot-welding robot, ~2.5 m tall with its gun; "
                  "balancer cylinder + piston close a loop between link_1 and link_2 "
                  "(edgefit loop_closure); tool0 at the flange, z out of it. Attach the "
                  "gun with weld_gun.urdf@tool0.");
  for (const char* link : {"base_link", "link_1", "link_2", "link_3", "link_4", "link_5", "link_6"}) {
    urdf.AddLink(link, std::string("meshes/") + link + ".stl", kRobotColour);
  }
  urdf.AddLink("balancer_cylinder", "meshes/balancer_cylinder.stl", kBalancerColour);
  urdf.AddLink("balancer_piston", "meshes/balancer_piston.stl", kBalancerColour);
  urdf.AddLink("tool0", "");
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                        Z = Eigen::Vector3d::UnitZ();
  // Limits of a 200 kg-class robot [rad]: axis 1 +-170 deg, 2 -69..+74 deg,
  // 3 -92..+115 deg, 4 +-190 deg, 5 +-125 deg, 6 +-350 deg.
  urdf.AddJoint(Revolute("joint_1", "base_link", "link_1", At(0, 0, L.j1_height), Z, -2.967, 2.967));
  urdf.AddJoint(Revolute("joint_2", "link_1", "link_2", Pose(Eigen::Translation3d(L.shoulder)), Y,
                         -1.2, 1.3));
  urdf.AddJoint(Revolute("joint_3", "link_2", "link_3", At(0, 0, L.upper_arm), Y, -1.6, 2.0));
  urdf.AddJoint(
      Revolute("joint_4", "link_3", "link_4", Pose(Eigen::Translation3d(L.forearm_root)), X, -3.316, 3.316));
  urdf.AddJoint(Revolute("joint_5", "link_4", "link_5", At(L.forearm, 0, 0), Y, -2.182, 2.182));
  urdf.AddJoint(Revolute("joint_6", "link_5", "link_6", At(L.wrist, 0, 0), X, -6.109, 6.109));
  urdf.AddJoint(Fixed("tool0_joint", "link_6", "tool0",
                      PoseFromXyzRpy(Eigen::Vector3d(L.flange, 0, 0), Eigen::Vector3d(0, M_PI_2, 0))));
  // Sub-chain: solved from joint_2 by the loop closure below.
  urdf.AddJoint(Revolute("balancer_cylinder_joint", "link_1", "balancer_cylinder",
                         Pose(Eigen::Translation3d(L.balancer_pivot)), Y, -0.8, 0.8));
  UrdfJointSpec piston = Revolute("balancer_piston_joint", "balancer_cylinder", "balancer_piston",
                                  Pose::Identity(), X, 0.42, 0.76);
  piston.type = JointType::kPrismatic;
  urdf.AddJoint(piston);
  LoopClosureSpec closure;
  closure.name = "balancer";
  closure.link_a = "balancer_piston";
  closure.link_b = "link_2";
  closure.p_link_b = L.crank_pin;
  closure.joints = {"balancer_cylinder_joint", "balancer_piston_joint"};
  urdf.AddLoopClosure(closure);
  return urdf.ToString();
}

std::string WeldGunUrdf() {
  const assets_internal::WeldGunLayout& G = assets_internal::GunLayout();
  UrdfWriter urdf("weld_gun",
                  "Servo spot-welding gun, ~1 m along +z from its mount (the robot's tool0): "
                  "body, transformer, servo motor, C-shaped fixed arm, moving electrode on "
                  "gun_joint (0 open .. stroke closed), tcp at the fixed electrode tip.");
  urdf.AddLink("gun_base", "meshes/gun_base.stl", kGunColour);
  urdf.AddLink("gun_fixed_arm", "meshes/gun_fixed_arm.stl", kGunColour);
  urdf.AddLink("gun_electrode", "meshes/gun_electrode.stl", kBalancerColour);
  urdf.AddLink("tcp", "");
  urdf.AddJoint(Fixed("gun_fixed_arm_joint", "gun_base", "gun_fixed_arm", Pose::Identity()));
  UrdfJointSpec stroke = Revolute("gun_joint", "gun_base", "gun_electrode",
                                  At(0, 0, G.electrode_joint_z), Eigen::Vector3d::UnitZ(), 0.0,
                                  G.stroke);
  stroke.type = JointType::kPrismatic;
  stroke.velocity = 0.5;
  urdf.AddJoint(stroke);
  urdf.AddJoint(Fixed("tcp_joint", "gun_fixed_arm", "tcp",
                      PoseFromXyzRpy(Eigen::Vector3d(0, 0, G.fixed_tip_z),
                                     Eigen::Vector3d(M_PI, 0, 0))));
  return urdf.ToString();
}

std::vector<NamedPosture> RobotPostures() {
  auto posture = [](const std::string& name, std::vector<double> q) {
    NamedPosture p{name, {}};
    const char* joints[] = {"joint_1", "joint_2", "joint_3", "joint_4",
                            "joint_5", "joint_6", "gun_joint"};
    for (int k = 0; k < 7; ++k) p.joint_values.emplace_back(joints[k], q[k]);
    return p;
  };
  // Upright with the gun pointing down; welding low and to the side; arm
  // raised and turned back, reaching over.
  return {posture("home", {0.0, 0.0, -0.45, 0.0, 1.55, 0.0, 0.02}),
          posture("weld_low", {0.7, 0.45, 0.0, -0.5, 0.6, 0.6, 0.09}),
          posture("raised", {-1.2, -0.35, -0.55, 0.6, 1.5, -1.0, 0.05})};
}

}  // namespace

Status GenerateRobotAsset(const std::string& out_dir) {
  const std::string dir = out_dir + "/robot";
  std::vector<assets_internal::LinkMesh> meshes = assets_internal::RobotLinkMeshes();
  for (assets_internal::LinkMesh& gun : assets_internal::WeldGunLinkMeshes()) {
    meshes.push_back(std::move(gun));
  }
  EDGEFIT_RETURN_IF_ERROR(assets_internal::WriteLinkMeshes(dir, meshes));
  EDGEFIT_RETURN_IF_ERROR(assets_internal::WriteTextFile(dir, "robot.urdf", RobotUrdf()));
  EDGEFIT_RETURN_IF_ERROR(assets_internal::WriteTextFile(dir, "weld_gun.urdf", WeldGunUrdf()));
  return assets_internal::WriteTextFile(dir, "postures.json", FormatPosturesJson(RobotPostures()));
}

Status GenerateBenchmarkAssets(const std::string& out_dir) {
  EDGEFIT_RETURN_IF_ERROR(GenerateRobotAsset(out_dir));
  return GenerateConveyorAsset(out_dir);
}

}  // namespace edgefit
