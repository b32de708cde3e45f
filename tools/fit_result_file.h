// Reading back a result.json of edgefit fit: its "inputs" name the model
// (URDF and attachments) it fitted; "joints" and "base" hold the values.
#ifndef EDGEFIT_TOOLS_FIT_RESULT_FILE_H_
#define EDGEFIT_TOOLS_FIT_RESULT_FILE_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/composition.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit::tools {

// result.json's "inputs": what a fit read, as absolute paths (the URDF,
// its attachments as --attach specs, the scans, the region of interest when
// given): enough for `edgefit report` and `edgefit world` to load the model
// and the scans again.
nlohmann::json FitInputsJson(const std::string& urdf, const std::vector<AttachSpec>& specs,
                             const std::vector<std::string>& scans,
                             const Eigen::AlignedBox3d* roi);

// PoseFromJson with an error naming `what`.
Status PoseFromRows(const nlohmann::json& rows, const std::string& what, Pose* T);

// The fitted model (loaded again from inputs.urdf and inputs.attach), its
// joint values (model order) and T_world_base from `result`, read from
// `path` (named in every error).
Status ReadFittedModel(const nlohmann::json& result, const std::string& path,
                       KinematicModel* model, std::vector<double>* q, Pose* T_world_base);

}  // namespace edgefit::tools

#endif  // EDGEFIT_TOOLS_FIT_RESULT_FILE_H_
