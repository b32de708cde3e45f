#include "edgefit/model/calibrated_urdf.h"

#include <cstdio>

#include "edgefit/core/atomic_file.h"
#include "edgefit/model/resource_path.h"
#include "edgefit/model/urdf_loader.h"

namespace edgefit {
namespace {

// `<origin xyz=".." rpy=".."/>` of T.
std::string OriginXml(const Pose& T) {
  const Eigen::Vector3d t = T.translation();
  const Eigen::Vector3d rpy = RpyFromRotation(T.linear());
  char line[256];
  std::snprintf(line, sizeof(line), "<origin xyz=\"%.9g %.9g %.9g\" rpy=\"%.9g %.9g %.9g\"/>",
                t.x(), t.y(), t.z(), rpy.x(), rpy.y(), rpy.z());
  return line;
}

std::string FixedJointXml(const std::string& name, const std::string& parent,
                          const std::string& child, const Pose& T_parent_child) {
  return "  <joint name=\"" + name + "\" type=\"fixed\">\n    <parent link=\"" + parent +
         "\"/>\n    <child link=\"" + child + "\"/>\n    " + OriginXml(T_parent_child) +
         "\n  </joint>\n";
}

// The URDF at `path`: its text between the <robot> start tag and </robot>,
// every mesh filename replaced by the file it resolves to.
Status RobotBody(const std::string& path, const ModelLoadOptions& options, std::string* head,
                 std::string* body) {
  std::string text;
  EDGEFIT_RETURN_IF_ERROR(ReadFileToString(path, &text));
  const size_t robot = text.find("<robot");
  const size_t open_end = robot == std::string::npos ? robot : text.find('>', robot);
  const size_t close = text.rfind("</robot>");
  if (open_end == std::string::npos || close == std::string::npos || close < open_end) {
    return Status::Error(path + ": no <robot> element");
  }
  *head = text.substr(0, open_end + 1);
  body->clear();
  const std::string key = "filename=\"";
  const std::vector<std::string> package_dirs = PackageDirs(options);
  size_t at = open_end + 1;
  for (size_t found; (found = text.find(key, at)) < close;) {
    const size_t begin = found + key.size();
    const size_t end = text.find('"', begin);
    if (end == std::string::npos || end > close) break;
    std::string resolved;
    const std::string uri = text.substr(begin, end - begin);
    if (!ResolveMeshPath(uri, path, package_dirs, &resolved).ok()) resolved = uri;
    *body += text.substr(at, begin - at) + resolved;
    at = end;
  }
  *body += text.substr(at, close - at);
  return Status::Ok();
}

}  // namespace

Status CalibratedUrdf(const std::string& urdf_path, const std::vector<AttachSpec>& attachments,
                      const KinematicModel& model, const Pose& T_world_base,
                      const std::vector<double>& q, const ModelLoadOptions& options,
                      std::string* out, const std::vector<std::string>& joint_notes) {
  if (q.size() != model.joints().size()) {
    return Status::Error("calibrated URDF: " + std::to_string(q.size()) + " joint values for " +
                         std::to_string(model.joints().size()) + " joints");
  }
  std::string head, body;
  EDGEFIT_RETURN_IF_ERROR(RobotBody(urdf_path, options, &head, &body));
  std::string text = head + "\n  <!-- edgefit fit: fitted joint values:";
  for (size_t j = 0; j < model.joints().size(); ++j) {
    if (!model.joints()[j].IsMoving()) continue;
    char value[160];
    std::snprintf(value, sizeof(value), " %s=%.9g", model.joints()[j].name.c_str(), q[j]);
    text += value;
    if (j < joint_notes.size() && !joint_notes[j].empty()) text += " [" + joint_notes[j] + "]";
  }
  const std::string& root = model.links()[static_cast<size_t>(model.root_link())].name;
  text +=
      " -->\n  <!-- edgefit fit: base pose in the scan's world frame -->\n"
      "  <link name=\"world\"/>\n" +
      FixedJointXml("world_to_" + root, "world", root, T_world_base) + body;
  ModelLoadOptions names_only = options;
  names_only.load_meshes = false;
  for (const AttachSpec& spec : attachments) {
    if (!spec.prefix.empty()) {
      return Status::Error("calibrated URDF: attachment " + spec.path + " has a name prefix");
    }
    KinematicModel attached;
    EDGEFIT_RETURN_IF_ERROR(LoadKinematicModel(spec.path, names_only, &attached));
    std::string attached_head, attached_body;
    EDGEFIT_RETURN_IF_ERROR(RobotBody(spec.path, options, &attached_head, &attached_body));
    const std::string& attached_root =
        attached.links()[static_cast<size_t>(attached.root_link())].name;
    text += "\n  <!-- attached: " + spec.path + " -->" + attached_body +
            FixedJointXml(spec.parent_link + "_to_" + attached_root, spec.parent_link,
                          attached_root, spec.T_parent_root);
  }
  *out = text + "</robot>\n";
  return Status::Ok();
}

}  // namespace edgefit
