// KinematicModel: a URDF tree of links and joints with per-link meshes
// (paper Sec. 3). Joint values are kept in one vector indexed like joints():
// radians for revolute/continuous, metres for prismatic, 0 for fixed.
//
// Independent joints are the non-fixed joints that are neither URDF mimic
// joints nor driven by a loop closure (paper Sec. 3.1 and 5.3: sub-chain
// joints follow the main chain). ResolveDependentJoints fills the others.
#ifndef EDGEFIT_MODEL_KINEMATIC_MODEL_H_
#define EDGEFIT_MODEL_KINEMATIC_MODEL_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

enum class JointType { kFixed, kRevolute, kContinuous, kPrismatic };
const char* JointTypeName(JointType type);  // "fixed", "revolute", ...

struct Joint {
  std::string name;
  JointType type = JointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  Pose T_parent_joint = Pose::Identity();            // URDF <origin>
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit, joint frame
  bool has_limits = false;  // false for continuous and fixed
  double lower = 0.0;       // [rad] or [m]
  double upper = 0.0;
  // URDF <limit> effort [N m] or [N] and velocity [rad/s] or [m/s]: not
  // used by the fit, carried to the files written from the model.
  double effort = 0.0;
  double velocity = 0.0;
  // URDF <mimic>: q = multiplier * q[mimic_joint] + offset.
  int mimic_joint = -1;
  double mimic_multiplier = 1.0;
  double mimic_offset = 0.0;
  // Index into KinematicModel::loop_closures() when a loop closure drives it.
  int loop_closure = -1;

  bool IsMoving() const { return type != JointType::kFixed; }
  bool IsIndependent() const { return IsMoving() && mimic_joint < 0 && loop_closure < 0; }
  // Transform of the child link in the parent link frame for value q.
  Pose T_parent_child(double q) const;
};

// One <visual> of a link, as written in the URDF.
struct Visual {
  enum class Kind { kMesh, kBox, kCylinder, kSphere };
  Kind kind = Kind::kMesh;
  Pose T_link_visual = Pose::Identity();
  std::string mesh_path;  // resolved absolute path (kMesh)
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  // [m] (kBox)
  double radius = 0.0;                                 // [m] (kCylinder, kSphere)
  double length = 0.0;                                 // [m] (kCylinder, along z)
  int triangle_count = 0;                              // after loading
};

struct Link {
  std::string name;
  int parent_joint = -1;          // -1 for the root
  std::vector<int> child_joints;  // in URDF order
  std::vector<Visual> visuals;
  TriangleMesh mesh;              // all visuals merged, in the link frame [m]
  std::string source;             // URDF file that defined it (main or attached)
};

// A sub-chain closes a loop: point_a on link_a must coincide with point_b on
// link_b (paper Sec. 3.1). The `joints` listed are solved numerically so that
// it holds, given every other joint.
struct LoopClosure {
  std::string name;
  int link_a = -1;
  Eigen::Vector3d p_link_a = Eigen::Vector3d::Zero();
  int link_b = -1;
  Eigen::Vector3d p_link_b = Eigen::Vector3d::Zero();
  std::vector<int> joints;
};

class KinematicModel {
 public:
  const std::string& name() const { return name_; }
  const std::vector<Link>& links() const { return links_; }
  const std::vector<Joint>& joints() const { return joints_; }
  const std::vector<LoopClosure>& loop_closures() const { return loop_closures_; }
  int root_link() const { return root_link_; }
  int LinkIndex(const std::string& name) const;   // -1 if absent
  int JointIndex(const std::string& name) const;  // -1 if absent

  // Joint indices in parents-first (breadth-first from the root) order.
  const std::vector<int>& joint_order() const { return joint_order_; }
  // The independent joints, parents first.
  std::vector<int> IndependentJoints() const;

  // A joint vector of zeros (clamped into the limits where 0 is outside them).
  // Dependent joints are left at 0 too: call ResolveDependentJoints after.
  std::vector<double> ZeroJoints() const;
  // Fills mimic and loop-closure joints from the independent ones, in
  // dependency order (a mimic of a loop-driven joint follows its solved
  // master; a closure waits for the mimic joints on its paths). Loop-closure
  // joints are warm-started from their values in *q (see loop_closure.h).
  // Fails when a loop closure cannot be met (residual above `tolerance` [m]),
  // keeping the best values found, or on a dependency cycle.
  Status ResolveDependentJoints(std::vector<double>* q, double tolerance = 1e-6) const;
  // T_world_link for every link, for full joint values q (size joints(),
  // dependent joints already resolved) and the root's pose T_world_root.
  std::vector<Pose> ForwardKinematics(const std::vector<double>& q,
                                      const Pose& T_world_root = Pose::Identity()) const;
  // Axis-aligned box of all link meshes posed by q.
  Eigen::AlignedBox3d BoundingBox(const std::vector<double>& q,
                                  const Pose& T_world_root = Pose::Identity()) const;

  // Building (used by the URDF loader and composition).
  std::string& mutable_name() { return name_; }
  std::vector<Link>& mutable_links() { return links_; }
  std::vector<Joint>& mutable_joints() { return joints_; }
  std::vector<LoopClosure>& mutable_loop_closures() { return loop_closures_; }
  // Recomputes root, child lists and joint order; fails on a non-tree.
  Status Finalize();

 private:
  std::string name_;
  std::vector<Link> links_;
  std::vector<Joint> joints_;
  std::vector<LoopClosure> loop_closures_;
  int root_link_ = -1;
  std::vector<int> joint_order_;
};

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_KINEMATIC_MODEL_H_
