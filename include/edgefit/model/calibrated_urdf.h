// The calibrated URDF of a fit (`edgefit fit --out_urdf`): the model as it
// was loaded (main URDF plus attached end effectors) placed in the scan's
// world frame, so a motion planner can load it in place of the scanned
// equipment.
#ifndef EDGEFIT_MODEL_CALIBRATED_URDF_H_
#define EDGEFIT_MODEL_CALIBRATED_URDF_H_

#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// The text of the main URDF at `urdf_path` with
//  - a link "world" and a fixed joint "world_to_<root>" at T_world_base,
//  - the fitted values of every moving joint of `model` in a comment
//    (URDF has no joint state), each followed by joint_notes[j] in
//    brackets when that is given and not empty (the fit's verdict),
//  - each attachment's links and joints, joined to its parent link by the
//    fixed joint "<parent_link>_to_<root>" at T_parent_root (the names
//    LoadModelWithAttachments gives),
//  - every mesh filename resolved to an absolute path (a relative or
//    package:// name would not resolve from where the file is written).
// `model` is the model loaded from urdf_path and `attachments`; q is
// indexed like model.joints(). Attachments with a name prefix are refused
// (their names would have to be rewritten in the XML).
Status CalibratedUrdf(const std::string& urdf_path, const std::vector<AttachSpec>& attachments,
                      const KinematicModel& model, const Pose& T_world_base,
                      const std::vector<double>& q, const ModelLoadOptions& options,
                      std::string* out, const std::vector<std::string>& joint_notes = {});

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_CALIBRATED_URDF_H_
