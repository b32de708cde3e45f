// The conveyance system as one URDF with STL meshes, plus three postures
// (paper Fig. 4b, Sec. 3.2 and 7.3). Geometry: conveyor_link_meshes.cc.
#include "asset_output.h"
#include "conveyor_layout.h"
#include "conveyor_link_meshes.h"
#include "edgefit/assets/benchmark_assets.h"
#include "edgefit/assets/posture_file.h"
#include "edgefit/assets/urdf_writer.h"

namespace edgefit {
namespace {

using assets_internal::At;

const Eigen::Vector4d kFrameColour(0.35, 0.45, 0.6, 1.0);
const Eigen::Vector4d kMovingColour(0.85, 0.75, 0.2, 1.0);

UrdfJointSpec Prismatic(const std::string& name, const std::string& parent,
                        const std::string& child, const Pose& origin, const Eigen::Vector3d& axis,
                        double lower, double upper) {
  UrdfJointSpec j;
  j.name = name;
  j.type = JointType::kPrismatic;
  j.parent = parent;
  j.child = child;
  j.T_parent_joint = origin;
  j.axis = axis;
  j.lower = lower;
  j.upper = upper;
  j.velocity = 0.5;
  return j;
}

UrdfJointSpec TipFrame(const std::string& parent, const std::string& tip, const Pose& origin) {
  UrdfJointSpec j;
  j.name = tip + "_joint";
  j.parent = parent;
  j.child = tip;
  j.T_parent_joint = origin;
  return j;
}

std::string ConveyorUrdf() {
  const assets_internal::ConveyorLayout& L = assets_internal::ConveyorLayoutValues();
  UrdfWriter urdf("conveyance_system",
                  "Conveyance system ~5.5 x 1.6 x 1.7 m: base frame, branched chain of six "
                  "prismatic joints (two carriages along x, each with a lifter along z; "
                  "lifter_2 with two clamps along +-y). tip_* frames mark the arm tips "
                  "(cone apexes).");
  urdf.AddLink("base_link", "meshes/base_link.stl", kFrameColour);
  for (const char* link : {"carriage_1", "lifter_1", "carriage_2", "lifter_2", "clamp_2_left",
                           "clamp_2_right"}) {
    urdf.AddLink(link, std::string("meshes/") + link + ".stl", kMovingColour);
  }
  for (const char* tip : {"tip_1_left", "tip_1_right", "tip_2_left", "tip_2_right"}) {
    urdf.AddLink(tip, "");
  }
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                        Z = Eigen::Vector3d::UnitZ();
  for (int k = 1; k <= 2; ++k) {
    const std::string n = std::to_string(k);
    const double x0 = (k == 1 ? -1.0 : 1.0) * L.carriage_x;
    urdf.AddJoint(Prismatic("carriage_" + n + "_joint", "base_link", "carriage_" + n,
                            At(x0, 0, L.rail_top), X, -L.carriage_travel, L.carriage_travel));
    urdf.AddJoint(Prismatic("lifter_" + n + "_joint", "carriage_" + n, "lifter_" + n,
                            At(0, 0, L.lifter_z), Z, 0.0, L.lifter_travel));
  }
  urdf.AddJoint(Prismatic("clamp_2_left_joint", "lifter_2", "clamp_2_left", At(0, L.clamp_y, L.clamp_z),
                          Y, 0.0, L.clamp_travel));
  urdf.AddJoint(Prismatic("clamp_2_right_joint", "lifter_2", "clamp_2_right",
                          At(0, -L.clamp_y, L.clamp_z), -Y, 0.0, L.clamp_travel));
  urdf.AddJoint(TipFrame("lifter_1", "tip_1_left", At(0, L.fixed_arm_y, L.tip_z)));
  urdf.AddJoint(TipFrame("lifter_1", "tip_1_right", At(0, -L.fixed_arm_y, L.tip_z)));
  urdf.AddJoint(TipFrame("clamp_2_left", "tip_2_left", At(0, 0, L.tip_z - L.clamp_z)));
  urdf.AddJoint(TipFrame("clamp_2_right", "tip_2_right", At(0, 0, L.tip_z - L.clamp_z)));
  return urdf.ToString();
}

std::vector<NamedPosture> ConveyorPostures() {
  auto posture = [](const std::string& name, std::vector<double> q) {
    NamedPosture p{name, {}};
    const char* joints[] = {"carriage_1_joint", "lifter_1_joint", "carriage_2_joint",
                            "lifter_2_joint", "clamp_2_left_joint", "clamp_2_right_joint"};
    for (int k = 0; k < 6; ++k) p.joint_values.emplace_back(joints[k], q[k]);
    return p;
  };
  // Carriages apart and low; moving with lifted parts; close together.
  return {posture("load", {-0.6, 0.05, 0.6, 0.05, 0.02, 0.02}),
          posture("transfer", {0.3, 0.18, 0.5, 0.12, 0.08, 0.08}),
          posture("handover", {0.7, 0.10, -0.4, 0.0, 0.11, 0.11})};
}

}  // namespace

Status GenerateConveyorAsset(const std::string& out_dir) {
  const std::string dir = out_dir + "/conveyor";
  EDGEFIT_RETURN_IF_ERROR(
      assets_internal::WriteLinkMeshes(dir, assets_internal::ConveyorLinkMeshes()));
  EDGEFIT_RETURN_IF_ERROR(assets_internal::WriteTextFile(dir, "conveyor.urdf", ConveyorUrdf()));
  return assets_internal::WriteTextFile(dir, "postures.json",
                                        FormatPosturesJson(ConveyorPostures()));
}

}  // namespace edgefit
