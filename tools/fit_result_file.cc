#include "fit_result_file.h"

#include <cstdio>
#include <filesystem>

#include "edgefit/core/pose_json.h"

namespace edgefit::tools {

using nlohmann::json;

json FitInputsJson(const std::string& urdf, const std::vector<AttachSpec>& specs,
                   const std::vector<std::string>& scans, const Eigen::AlignedBox3d* roi) {
  namespace fs = std::filesystem;
  json attach = json::array();
  for (const AttachSpec& a : specs) {
    std::string spec = fs::absolute(a.path).string() + "@" + a.parent_link;
    if (!a.T_parent_root.isApprox(Pose::Identity())) {
      const Eigen::Vector3d t = a.T_parent_root.translation();
      const Eigen::Vector3d rpy = RpyFromRotation(a.T_parent_root.linear());
      char pose[200];
      std::snprintf(pose, sizeof(pose), ":%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", t.x(), t.y(),
                    t.z(), rpy.x(), rpy.y(), rpy.z());
      spec += pose;
    }
    attach.push_back(spec);
  }
  json scan = json::array();
  for (const std::string& path : scans) scan.push_back(fs::absolute(path).string());
  json inputs = {{"urdf", fs::absolute(urdf).string()}, {"attach", attach}, {"scan", scan}};
  if (roi != nullptr) {
    inputs["roi"] = {roi->min().x(), roi->min().y(), roi->min().z(),
                     roi->max().x(), roi->max().y(), roi->max().z()};
  }
  return inputs;
}

Status PoseFromRows(const json& rows, const std::string& what, Pose* T) {
  return PoseFromJson(rows, T) ? Status::Ok()
                               : Status::Error(what + ": not a 4 x 4 rigid transform");
}

Status ReadFittedModel(const json& result, const std::string& path, KinematicModel* model,
                       std::vector<double>* q, Pose* T_world_base) {
  if (!result.is_object() || !result.contains("inputs") || !result.contains("joints") ||
      !result.contains("base")) {
    return Status::Error(path + ": not a result.json of edgefit fit with its inputs "
                                "(\"inputs\", \"joints\", \"base\")");
  }
  const json& inputs = result["inputs"];
  if (!inputs.is_object() || !inputs.contains("urdf") || !inputs["urdf"].is_string()) {
    return Status::Error(path + ": inputs.urdf missing");
  }
  std::string attach;
  for (const json& a : inputs.value("attach", json::array())) {
    if (!a.is_string()) return Status::Error(path + ": inputs.attach holds a non-string");
    attach += (attach.empty() ? "" : ",") + a.get<std::string>();
  }
  std::vector<AttachSpec> specs;
  EDGEFIT_RETURN_IF_ERROR(ParseAttachSpecList(attach, &specs));
  EDGEFIT_RETURN_IF_ERROR(
      LoadModelWithAttachments(inputs["urdf"].get<std::string>(), specs, ModelLoadOptions(), model));
  q->assign(model->joints().size(), 0.0);
  for (size_t j = 0; j < model->joints().size(); ++j) {
    const Joint& joint = model->joints()[j];
    if (!joint.IsMoving()) continue;
    const json& v = result["joints"].value(joint.name, json());
    if (!v.is_number()) {
      return Status::Error(path + ": joint '" + joint.name + "' of " +
                           inputs["urdf"].get<std::string>() + " has no value");
    }
    (*q)[j] = v.get<double>();
  }
  return PoseFromRows(result["base"].value("T_world_base", json()), path + ": base.T_world_base",
                      T_world_base);
}

}  // namespace edgefit::tools
