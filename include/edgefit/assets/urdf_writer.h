// Writing URDF text for the generated benchmark models and the planning
// world (edgefit/world): links with one mesh visual each (and the same mesh
// as their collision when asked), joints with limits and mimics, and the
// edgefit <loop_closure> extension (loop_closure.h). Numbers are printed with a fixed format ("%.9g", -0
// written as 0), so the same model always gives the same bytes.
#ifndef EDGEFIT_ASSETS_URDF_WRITER_H_
#define EDGEFIT_ASSETS_URDF_WRITER_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/loop_closure.h"

namespace edgefit {

struct UrdfJointSpec {
  std::string name;
  JointType type = JointType::kFixed;
  std::string parent, child;                        // link names
  Pose T_parent_joint = Pose::Identity();           // URDF <origin>
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // joint frame (moving joints)
  double lower = 0.0, upper = 0.0;                  // [rad] or [m] (revolute, prismatic)
  double effort = 1000.0;                           // [N m] or [N]
  double velocity = 1.0;                            // [rad/s] or [m/s]
  // <mimic>: q = multiplier * q[mimic] + offset; empty: none.
  std::string mimic;
  double mimic_multiplier = 1.0, mimic_offset = 0.0;
};

class UrdfWriter {
 public:
  // `comment` (may be empty) is written as an XML comment under the header;
  // `generator` names what wrote the file, in the first comment.
  UrdfWriter(std::string robot_name, std::string comment,
             std::string generator = "edgefit_make_assets (src/assets)");

  // A link whose visual is the mesh file `mesh_uri` (relative to the URDF)
  // at the link origin, or no visual when `mesh_uri` is empty (a frame).
  // `rgba` sets a named material colour for viewers; `collision`: the same
  // mesh is the link's collision geometry too; `extra_collision`: more mesh
  // files (relative to the URDF) of its collision geometry.
  void AddLink(const std::string& name, const std::string& mesh_uri,
               const Eigen::Vector4d& rgba = Eigen::Vector4d(0.7, 0.7, 0.7, 1.0),
               bool collision = false, const std::vector<std::string>& extra_collision = {});
  void AddJoint(const UrdfJointSpec& joint);
  void AddLoopClosure(const LoopClosureSpec& closure);

  std::string ToString() const;

 private:
  std::string name_;
  std::string comment_;
  std::string generator_;
  std::vector<std::string> links_, joints_, closures_;
};

// "%.9g" with -0 printed as 0.
std::string FormatUrdfNumber(double value);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_URDF_WRITER_H_
