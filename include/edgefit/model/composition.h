// Composition (paper Sec. 3.1): an end effector kept in its own URDF is
// attached to a link of the main model by a fixed joint, so that robots and
// tools can be combined freely.
#ifndef EDGEFIT_MODEL_COMPOSITION_H_
#define EDGEFIT_MODEL_COMPOSITION_H_

#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {

struct AttachSpec {
  std::string path;         // URDF of the attached model (end effector).
  std::string parent_link;  // Link of the main model it is mounted on.
  // Pose of the attached model's root link in the parent link frame.
  Pose T_parent_root = Pose::Identity();
  // Prepended to every attached link and joint name (default none). Names
  // that clash with the main model are an error, not silently renamed: a
  // prefix such as "gun_" is the way to attach the same tool twice.
  std::string prefix;
};

// Parses the command-line syntax "eef.urdf@link_6" or
// "eef.urdf@link_6:x,y,z,roll,pitch,yaw" (metres, radians, URDF rpy). The
// last '@' separates the path. One spec only: the caller splits lists.
Status ParseAttachSpec(const std::string& spec, AttachSpec* attach);

// Parses a comma-separated list of specs as given to --attach, e.g.
// "gun.urdf@tool0,cam.urdf@link_3:0,0,0.1,0,0,0". A comma inside a pose
// belongs to the pose (six numbers follow the ':'), so splitting the list
// naively on commas would be wrong. An empty list gives no specs.
Status ParseAttachSpecList(const std::string& list, std::vector<AttachSpec>* specs);

// Loads spec.path and adds its links, joints and loop closures to *model,
// joined by a fixed joint "<parent_link>_to_<root>" (prefixed root name)
// with origin T_parent_root. Attached links keep Link::source = spec.path.
// On failure *model is unchanged.
Status AttachModel(const AttachSpec& spec, const ModelLoadOptions& options, KinematicModel* model);

// The main URDF with every attachment applied in order (a later spec may
// name a link of an earlier attachment as its parent).
Status LoadModelWithAttachments(const std::string& urdf_path, const std::vector<AttachSpec>& specs,
                                const ModelLoadOptions& options, KinematicModel* model);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_COMPOSITION_H_
