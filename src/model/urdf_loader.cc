#include "edgefit/model/urdf_loader.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "edgefit/model/loop_closure.h"
#include "edgefit/model/mesh_loader.h"
#include "edgefit/model/primitive_meshes.h"
#include "edgefit/model/resource_path.h"
#include "urdf_xml_scan.h"

namespace edgefit {

bool ModelLoadOptions::IsValid(std::string* error) const {
  if (cylinder_segments < 3) {
    *error = "cylinder_segments must be >= 3";
    return false;
  }
  if (sphere_subdivisions < 0 || sphere_subdivisions > 7) {
    *error = "sphere_subdivisions must be in [0, 7]";
    return false;
  }
  return true;
}

namespace {

// Collects urdfdom's console_bridge errors while installed (instead of
// printing them), so the caller can fold them into one Status line.
class CapturingOutputHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error_.empty()) {
      first_error_ = text;
    }
  }
  const std::string& first_error() const { return first_error_; }

 private:
  std::string first_error_;
};

Pose ToPose(const urdf::Pose& p) {
  Pose T = Pose::Identity();
  T.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
  T.rotate(Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized());
  return T;
}

Status ParseWithUrdfdom(const std::string& xml, urdf::ModelInterfaceSharedPtr* urdf_model) {
  static std::mutex mutex;  // console_bridge's handler is process-global.
  std::lock_guard<std::mutex> lock(mutex);
  CapturingOutputHandler handler;
  console_bridge::useOutputHandler(&handler);
  try {
    *urdf_model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    console_bridge::restorePreviousOutputHandler();
    return Status::Error(std::string("urdfdom: ") + e.what());
  }
  console_bridge::restorePreviousOutputHandler();
  // urdfdom skips some elements it cannot parse (a box of size "inf") and
  // returns the rest: an error it logged fails the load all the same.
  if (*urdf_model == nullptr || !handler.first_error().empty()) {
    return Status::Error("not a valid URDF: " +
                         (handler.first_error().empty() ? "urdfdom failed" : handler.first_error()));
  }
  return Status::Ok();
}

// A <visual> or a <collision> (the same origin and geometry).
template <typename Element>
Status LoadVisual(const Element& urdf_visual, const std::string& urdf_path,
                  const ModelLoadOptions& options, const std::vector<std::string>& package_dirs,
                  std::map<std::string, TriangleMesh>* mesh_cache, Visual* visual,
                  TriangleMesh* link_mesh) {
  visual->T_link_visual = ToPose(urdf_visual.origin);
  const urdf::Geometry* geometry = urdf_visual.geometry.get();
  if (geometry == nullptr) return Status::Error("a visual or collision without geometry");
  auto size_ok = [](double x) { return std::isfinite(x) && x > 0.0; };
  TriangleMesh mesh;
  switch (geometry->type) {
    case urdf::Geometry::BOX: {
      const urdf::Vector3& d = static_cast<const urdf::Box*>(geometry)->dim;
      visual->kind = Visual::Kind::kBox;
      visual->box_size = Eigen::Vector3d(d.x, d.y, d.z);
      if (!size_ok(d.x) || !size_ok(d.y) || !size_ok(d.z)) {
        return Status::Error("box size must be three finite lengths > 0");
      }
      if (options.load_meshes) mesh = MakeBoxMesh(visual->box_size);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto* c = static_cast<const urdf::Cylinder*>(geometry);
      visual->kind = Visual::Kind::kCylinder;
      visual->radius = c->radius;
      visual->length = c->length;
      if (!size_ok(c->radius) || !size_ok(c->length)) {
        return Status::Error("cylinder radius and length must be finite and > 0");
      }
      if (options.load_meshes) mesh = MakeCylinderMesh(c->radius, c->length, options.cylinder_segments);
      break;
    }
    case urdf::Geometry::SPHERE: {
      visual->kind = Visual::Kind::kSphere;
      visual->radius = static_cast<const urdf::Sphere*>(geometry)->radius;
      if (!size_ok(visual->radius)) return Status::Error("sphere radius must be finite and > 0");
      if (options.load_meshes) mesh = MakeSphereMesh(visual->radius, options.sphere_subdivisions);
      break;
    }
    case urdf::Geometry::MESH: {
      const auto* m = static_cast<const urdf::Mesh*>(geometry);
      visual->kind = Visual::Kind::kMesh;
      visual->mesh_scale = Eigen::Vector3d(m->scale.x, m->scale.y, m->scale.z);
      if (!visual->mesh_scale.allFinite() || (visual->mesh_scale.array() == 0.0).any()) {
        return Status::Error("mesh '" + m->filename + "': scale must be finite and non-zero");
      }
      EDGEFIT_RETURN_IF_ERROR(
          ResolveMeshPath(m->filename, urdf_path, package_dirs, &visual->mesh_path));
      if (!options.load_meshes) break;
      auto it = mesh_cache->find(visual->mesh_path);
      if (it == mesh_cache->end()) {
        TriangleMesh loaded;
        EDGEFIT_RETURN_IF_ERROR(LoadMesh(visual->mesh_path, Eigen::Vector3d::Ones(), &loaded));
        it = mesh_cache->emplace(visual->mesh_path, std::move(loaded)).first;
      }
      mesh = it->second;
      ScaleMesh(visual->mesh_scale, &mesh);
      break;
    }
  }
  visual->triangle_count = static_cast<int>(mesh.triangles.size());
  link_mesh->Append(mesh, visual->T_link_visual);
  return Status::Ok();
}

Status ParseModel(const std::string& xml, const std::string& urdf_path,
                  const ModelLoadOptions& options, KinematicModel* model) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("bad load options: " + error);
  UrdfXmlScan scan;
  EDGEFIT_RETURN_IF_ERROR(ScanUrdfXml(xml, &scan));
  urdf::ModelInterfaceSharedPtr urdf_model;
  EDGEFIT_RETURN_IF_ERROR(ParseWithUrdfdom(xml, &urdf_model));

  const std::vector<std::string> package_dirs = PackageDirs(options);

  KinematicModel out;
  out.mutable_name() = urdf_model->getName();
  std::map<std::string, TriangleMesh> mesh_cache;  // Resolved path -> unscaled mesh.
  for (const std::string& link_name : scan.link_names) {
    urdf::LinkConstSharedPtr urdf_link = urdf_model->getLink(link_name);
    if (urdf_link == nullptr) return Status::Error("link '" + link_name + "' lost by urdfdom");
    Link link;
    link.name = link_name;
    link.source = urdf_path;
    std::vector<urdf::CollisionSharedPtr> collisions = urdf_link->collision_array;
    if (collisions.empty() && urdf_link->collision != nullptr) collisions.push_back(urdf_link->collision);
    std::vector<urdf::VisualSharedPtr> visuals = urdf_link->visual_array;
    if (visuals.empty() && urdf_link->visual != nullptr) visuals.push_back(urdf_link->visual);
    const auto load = [&](const auto& elements) -> Status {
      for (const auto& element : elements) {
        Visual visual;
        const Status status = LoadVisual(*element, urdf_path, options, package_dirs, &mesh_cache,
                                         &visual, &link.mesh);
        if (!status.ok()) return status.WithContext("link '" + link_name + "'");
        link.visuals.push_back(visual);
      }
      return Status::Ok();
    };
    EDGEFIT_RETURN_IF_ERROR(options.collision_geometry && !collisions.empty() ? load(collisions)
                                                                              : load(visuals));
    out.mutable_links().push_back(std::move(link));
  }
  for (const std::string& joint_name : scan.joint_names) {
    urdf::JointConstSharedPtr u = urdf_model->getJoint(joint_name);
    const std::string where = "joint '" + joint_name + "'";
    if (u == nullptr) return Status::Error(where + ": lost by urdfdom");
    Joint joint;
    joint.name = joint_name;
    switch (u->type) {
      case urdf::Joint::REVOLUTE: joint.type = JointType::kRevolute; break;
      case urdf::Joint::CONTINUOUS: joint.type = JointType::kContinuous; break;
      case urdf::Joint::PRISMATIC: joint.type = JointType::kPrismatic; break;
      case urdf::Joint::FIXED: joint.type = JointType::kFixed; break;
      default: return Status::Error(where + ": unsupported type");
    }
    joint.parent_link = out.LinkIndex(u->parent_link_name);
    joint.child_link = out.LinkIndex(u->child_link_name);
    if (joint.parent_link < 0 || joint.child_link < 0) {
      return Status::Error(where + ": unknown parent '" + u->parent_link_name + "' or child '" +
                           u->child_link_name + "'");
    }
    joint.T_parent_joint = ToPose(u->parent_to_joint_origin_transform);
    if (joint.IsMoving()) {
      const Eigen::Vector3d axis(u->axis.x, u->axis.y, u->axis.z);
      if (!(axis.norm() > 1e-12)) return Status::Error(where + ": zero axis");
      joint.axis = axis.normalized();  // URDF does not require a unit axis.
    }
    if (joint.IsMoving() && u->limits != nullptr) {
      joint.effort = u->limits->effort;
      joint.velocity = u->limits->velocity;
    }
    if ((joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic) &&
        u->limits != nullptr) {
      joint.has_limits = true;
      joint.lower = u->limits->lower;
      joint.upper = u->limits->upper;
      if (joint.lower > joint.upper) {
        return Status::Error(where + ": lower limit above upper limit");
      }
    }
    out.mutable_joints().push_back(joint);
  }
  for (size_t j = 0; j < scan.joint_names.size(); ++j) {
    urdf::JointConstSharedPtr u = urdf_model->getJoint(scan.joint_names[j]);
    if (u->mimic == nullptr) continue;
    Joint& joint = out.mutable_joints()[j];
    joint.mimic_joint = out.JointIndex(u->mimic->joint_name);
    if (joint.mimic_joint < 0 || !joint.IsMoving()) {
      return Status::Error("joint '" + joint.name + "': mimics unknown joint '" +
                           u->mimic->joint_name + "' or is fixed");
    }
    joint.mimic_multiplier = u->mimic->multiplier;
    joint.mimic_offset = u->mimic->offset;
  }
  // Tree structure first (loop closures need link indices only).
  EDGEFIT_RETURN_IF_ERROR(out.Finalize());
  for (const LoopClosureSpec& spec : scan.loop_closures) {
    EDGEFIT_RETURN_IF_ERROR(AddLoopClosure(spec, &out));
  }
  EDGEFIT_RETURN_IF_ERROR(out.Finalize());
  *model = std::move(out);
  return Status::Ok();
}

}  // namespace

std::vector<std::string> PackageDirs(const ModelLoadOptions& options) {
  std::vector<std::string> package_dirs = options.package_dirs;
  const char* ros_package_path = std::getenv("ROS_PACKAGE_PATH");
  if (options.use_ros_package_path && ros_package_path != nullptr) {
    std::istringstream in(ros_package_path);
    for (std::string dir; std::getline(in, dir, ':');) {
      if (!dir.empty()) package_dirs.push_back(dir);
    }
  }
  return package_dirs;
}

Status ParseKinematicModel(const std::string& xml, const std::string& urdf_path,
                           const ModelLoadOptions& options, KinematicModel* model) {
  return ParseModel(xml, urdf_path, options, model).WithContext(urdf_path);
}

Status LoadKinematicModel(const std::string& urdf_path, const ModelLoadOptions& options,
                          KinematicModel* model) {
  std::ifstream file(urdf_path, std::ios::binary);
  if (!file) return Status::Error("cannot open file").WithContext(urdf_path);
  std::stringstream buffer;
  buffer << file.rdbuf();
  return ParseKinematicModel(buffer.str(), urdf_path, options, model);
}

}  // namespace edgefit
