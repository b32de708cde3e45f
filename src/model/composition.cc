#include "edgefit/model/composition.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace edgefit {

Status ParseAttachSpec(const std::string& spec, AttachSpec* attach) {
  const std::string usage = "attach spec '" + spec +
                            "': expected FILE.urdf@PARENT_LINK[:x,y,z,roll,pitch,yaw] "
                            "(metres, radians)";
  const size_t at = spec.rfind('@');
  if (at == std::string::npos || at == 0 || at + 1 == spec.size()) return Status::Error(usage);
  AttachSpec out;
  out.path = spec.substr(0, at);
  const std::string rest = spec.substr(at + 1);
  const size_t colon = rest.find(':');
  out.parent_link = rest.substr(0, colon);
  if (out.parent_link.empty()) return Status::Error(usage);
  if (colon != std::string::npos) {
    const std::string numbers = rest.substr(colon + 1);
    std::vector<double> values;
    size_t begin = 0;
    while (true) {
      const size_t comma = numbers.find(',', begin);
      const std::string token = numbers.substr(begin, comma - begin);
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(token.c_str(), &end);
      if (token.empty() || end != token.c_str() + token.size() || errno != 0 ||
          !std::isfinite(value)) {
        return Status::Error(usage + ": bad number '" + token + "'");
      }
      values.push_back(value);
      if (comma == std::string::npos) break;
      begin = comma + 1;
    }
    if (values.size() != 6) return Status::Error(usage + ": need 6 numbers");
    out.T_parent_root = PoseFromXyzRpy(Eigen::Vector3d(values[0], values[1], values[2]),
                                       Eigen::Vector3d(values[3], values[4], values[5]));
  }
  *attach = std::move(out);
  return Status::Ok();
}

Status ParseAttachSpecList(const std::string& list, std::vector<AttachSpec>* specs) {
  std::vector<std::string> items;
  size_t begin = 0;
  while (begin <= list.size() && !list.empty()) {
    const size_t comma = std::min(list.find(',', begin), list.size());
    const std::string token = list.substr(begin, comma - begin);
    // Continue a pose "@link:x,y,..." until it holds its six numbers.
    bool in_pose = false;
    if (!items.empty()) {
      const std::string& last = items.back();
      const size_t at = last.rfind('@');
      const size_t colon = at == std::string::npos ? std::string::npos : last.find(':', at);
      in_pose = colon != std::string::npos &&
                std::count(last.begin() + colon, last.end(), ',') < 5;
    }
    if (in_pose) {
      items.back() += "," + token;
    } else {
      items.push_back(token);
    }
    begin = comma + 1;
  }
  std::vector<AttachSpec> out;
  for (const std::string& item : items) {
    AttachSpec spec;
    EDGEFIT_RETURN_IF_ERROR(ParseAttachSpec(item, &spec));
    out.push_back(std::move(spec));
  }
  *specs = std::move(out);
  return Status::Ok();
}

Status LoadModelWithAttachments(const std::string& urdf_path, const std::vector<AttachSpec>& specs,
                                const ModelLoadOptions& options, KinematicModel* model) {
  KinematicModel out;
  EDGEFIT_RETURN_IF_ERROR(LoadKinematicModel(urdf_path, options, &out));
  for (const AttachSpec& spec : specs) EDGEFIT_RETURN_IF_ERROR(AttachModel(spec, options, &out));
  *model = std::move(out);
  return Status::Ok();
}

Status AttachModel(const AttachSpec& spec, const ModelLoadOptions& options, KinematicModel* model) {
  const int parent = model->LinkIndex(spec.parent_link);
  if (parent < 0) {
    return Status::Error("attach " + spec.path + ": no link '" + spec.parent_link + "' in model '" +
                         model->name() + "'");
  }
  KinematicModel attached;
  EDGEFIT_RETURN_IF_ERROR(LoadKinematicModel(spec.path, options, &attached));
  KinematicModel merged = *model;
  const int link_offset = static_cast<int>(merged.links().size());
  const int joint_offset = static_cast<int>(merged.joints().size());
  for (Link link : attached.links()) {
    link.name = spec.prefix + link.name;
    if (merged.LinkIndex(link.name) >= 0) {
      return Status::Error("attach " + spec.path + ": link name '" + link.name +
                           "' already in the model (give a prefix)");
    }
    merged.mutable_links().push_back(std::move(link));
  }
  auto add_joint = [&](Joint joint) {
    if (merged.JointIndex(joint.name) >= 0) {
      return Status::Error("attach " + spec.path + ": joint name '" + joint.name +
                           "' already in the model (give a prefix)");
    }
    merged.mutable_joints().push_back(std::move(joint));
    return Status::Ok();
  };
  for (Joint joint : attached.joints()) {
    joint.name = spec.prefix + joint.name;
    joint.parent_link += link_offset;
    joint.child_link += link_offset;
    if (joint.mimic_joint >= 0) joint.mimic_joint += joint_offset;
    EDGEFIT_RETURN_IF_ERROR(add_joint(std::move(joint)));
  }
  for (LoopClosure closure : attached.loop_closures()) {
    closure.name = spec.prefix + closure.name;
    closure.link_a += link_offset;
    closure.link_b += link_offset;
    for (int& j : closure.joints) j += joint_offset;
    merged.mutable_loop_closures().push_back(std::move(closure));
  }
  Joint mount;
  mount.name = spec.parent_link + "_to_" + spec.prefix + attached.links()[attached.root_link()].name;
  mount.type = JointType::kFixed;
  mount.parent_link = parent;
  mount.child_link = link_offset + attached.root_link();
  mount.T_parent_joint = spec.T_parent_root;
  EDGEFIT_RETURN_IF_ERROR(add_joint(std::move(mount)));
  EDGEFIT_RETURN_IF_ERROR(merged.Finalize().WithContext("attach " + spec.path));
  *model = std::move(merged);
  return Status::Ok();
}

}  // namespace edgefit
