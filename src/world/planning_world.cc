#include "edgefit/world/planning_world.h"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <system_error>
#include <utility>

#include "edgefit/assets/stl_writer.h"
#include "edgefit/assets/urdf_writer.h"
#include "edgefit/core/atomic_file.h"
#include "edgefit/io/joint_states.h"
#include "edgefit/model/loop_closure.h"
#include "edgefit/model/mesh_ply.h"
#include "edgefit/world/collision_pairs.h"

namespace edgefit {
namespace {

namespace fs = std::filesystem;

constexpr char kGenerator[] = "edgefit world (src/world)";

}  // namespace

Status CheckWorldMachines(const std::vector<WorldMachine>& machines) {
  if (machines.empty()) return Status::Error("world: no machines");
  std::set<std::string> names;
  for (const WorldMachine& m : machines) {
    const std::string where = m.source.empty() ? "world: machine '" + m.name + "'" : m.source;
    if (m.model == nullptr) return Status::Error(where + ": no model");
    if (m.name.empty()) return Status::Error(where + ": an empty machine name");
    for (const char c : m.name) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') {
        return Status::Error(where + ": machine name '" + m.name +
                             "' may hold only letters, digits, '_' and '-'");
      }
    }
    if (!names.insert(m.name).second) {
      return Status::Error(where + ": machine name '" + m.name + "' is given twice");
    }
    if (m.q.size() != m.model->joints().size()) {
      return Status::Error(where + ": " + std::to_string(m.q.size()) + " joint values for " +
                           std::to_string(m.model->joints().size()) + " joints");
    }
    for (const double v : m.q) {
      if (!std::isfinite(v)) return Status::Error(where + ": a joint value is not finite");
    }
    if (!m.attached.empty() && m.attached.size() != m.model->links().size()) {
      return Status::Error(where + ": attached meshes for " + std::to_string(m.attached.size()) +
                           " links of " + std::to_string(m.model->links().size()));
    }
    if (!m.T_world_base.matrix().allFinite()) {
      return Status::Error(where + ": the base pose is not finite");
    }
  }
  return Status::Ok();
}

namespace {

// A file name for a link's mesh: the prefixed name, other characters '_'.
std::string MeshFile(const std::string& prefixed_link, const std::string& suffix = "") {
  std::string file = prefixed_link;
  for (char& c : file) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  }
  return "meshes/" + file + suffix + ".stl";
}

bool HasAttached(const WorldMachine& m, size_t link) {
  return !m.attached.empty() && !m.attached[link].empty();
}

// cell.urdf (frozen: every joint fixed at its fitted value).
std::string CellUrdf(const std::vector<WorldMachine>& machines, bool frozen) {
  UrdfWriter urdf("cell",
                  frozen ? "every joint fixed at the value edgefit fitted"
                         : "the fitted machines; joint values in joint_states.yaml and cell.srdf",
                  kGenerator);
  urdf.AddLink("world", "");
  for (const WorldMachine& m : machines) {
    const KinematicModel& model = *m.model;
    const std::string prefix = m.name + "_";
    for (size_t l = 0; l < model.links().size(); ++l) {
      const Link& link = model.links()[l];
      std::vector<std::string> attached;
      if (HasAttached(m, l)) attached.push_back(MeshFile(prefix + link.name, "_attached"));
      urdf.AddLink(prefix + link.name, link.mesh.empty() ? "" : MeshFile(prefix + link.name),
                   Eigen::Vector4d(0.7, 0.7, 0.7, 1.0), /*collision=*/true, attached);
    }
    UrdfJointSpec base;
    base.name = "world_to_" + m.name;
    base.parent = "world";
    base.child = prefix + model.links()[static_cast<size_t>(model.root_link())].name;
    base.T_parent_joint = m.T_world_base;
    urdf.AddJoint(base);
    for (size_t j = 0; j < model.joints().size(); ++j) {
      const Joint& joint = model.joints()[j];
      UrdfJointSpec spec;
      spec.name = prefix + joint.name;
      spec.parent = prefix + model.links()[static_cast<size_t>(joint.parent_link)].name;
      spec.child = prefix + model.links()[static_cast<size_t>(joint.child_link)].name;
      if (frozen) {
        spec.T_parent_joint = joint.T_parent_child(m.q[j]);
      } else {
        spec.type = joint.type;
        spec.T_parent_joint = joint.T_parent_joint;
        spec.axis = joint.axis;
        spec.lower = joint.lower;
        spec.upper = joint.upper;
        spec.effort = joint.effort;
        spec.velocity = joint.velocity;
        if (joint.mimic_joint >= 0) {
          spec.mimic = prefix + model.joints()[static_cast<size_t>(joint.mimic_joint)].name;
          spec.mimic_multiplier = joint.mimic_multiplier;
          spec.mimic_offset = joint.mimic_offset;
        }
      }
      urdf.AddJoint(spec);
    }
    if (frozen) continue;
    for (const LoopClosure& closure : model.loop_closures()) {
      LoopClosureSpec spec;
      spec.name = prefix + closure.name;
      spec.link_a = prefix + model.links()[static_cast<size_t>(closure.link_a)].name;
      spec.link_b = prefix + model.links()[static_cast<size_t>(closure.link_b)].name;
      spec.p_link_a = closure.p_link_a;
      spec.p_link_b = closure.p_link_b;
      for (const int j : closure.joints) {
        spec.joints.push_back(prefix + model.joints()[static_cast<size_t>(j)].name);
      }
      urdf.AddLoopClosure(spec);
    }
  }
  return urdf.ToString();
}

// Each machine's model with its links' collision geometry (the mesh and
// what rides on it) as Link::mesh: what cell.urdf's <collision> elements
// hold.
std::vector<KinematicModel> CollisionModels(const std::vector<WorldMachine>& machines) {
  std::vector<KinematicModel> models;
  for (const WorldMachine& m : machines) {
    models.push_back(*m.model);
    for (size_t l = 0; l < m.attached.size(); ++l) {
      models.back().mutable_links()[l].mesh.Append(m.attached[l], Pose::Identity());
    }
  }
  return models;
}

// cell.srdf: MoveIt's semantic description of cell.urdf.
std::string CellSrdf(const std::vector<WorldMachine>& machines) {
  const std::vector<KinematicModel> collision = CollisionModels(machines);
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<!-- Generated by " << kGenerator
     << "; do not edit by hand. -->\n<robot name=\"cell\">\n";
  for (const WorldMachine& m : machines) {
    const std::string prefix = m.name + "_";
    os << "  <group name=\"" << m.name << "\">\n";
    for (const Joint& joint : m.model->joints()) {
      os << "    <joint name=\"" << prefix << joint.name << "\"/>\n";
    }
    os << "  </group>\n";
  }
  for (const WorldMachine& m : machines) {
    os << "  <group_state name=\"as_scanned\" group=\"" << m.name << "\">\n";
    for (size_t j = 0; j < m.model->joints().size(); ++j) {
      const Joint& joint = m.model->joints()[j];
      if (!joint.IsIndependent()) continue;
      os << "    <joint name=\"" << m.name << "_" << joint.name << "\" value=\"" << FormatUrdfNumber(m.q[j])
         << "\"/>\n";
    }
    os << "  </group_state>\n";
  }
  for (size_t i = 0; i < machines.size(); ++i) {
    const WorldMachine& m = machines[i];
    for (const LinkPair& pair : DisabledCollisionPairs(collision[i], m.q, CollisionPairsOptions())) {
      os << "  <disable_collisions link1=\"" << m.name << "_"
         << m.model->links()[static_cast<size_t>(pair.link_a)].name << "\" link2=\"" << m.name
         << "_" << m.model->links()[static_cast<size_t>(pair.link_b)].name << "\" reason=\""
         << pair.reason << "\"/>\n";
    }
  }
  for (size_t i = 0; i < machines.size(); ++i) {
    const WorldMachine& a = machines[i];
    const std::vector<Pose> T_a = a.model->ForwardKinematics(a.q, a.T_world_base);
    for (size_t k = i + 1; k < machines.size(); ++k) {
      const WorldMachine& b = machines[k];
      const std::vector<Pose> T_b = b.model->ForwardKinematics(b.q, b.T_world_base);
      for (const auto& [la, lb] : TouchingLinks(collision[i], T_a, collision[k], T_b)) {
        os << "  <disable_collisions link1=\"" << a.name << "_"
           << a.model->links()[static_cast<size_t>(la)].name << "\" link2=\"" << b.name << "_"
           << b.model->links()[static_cast<size_t>(lb)].name << "\" reason=\"Default\"/>\n";
      }
    }
  }
  os << "</robot>\n";
  return os.str();
}

std::string CellJointStates(const std::vector<WorldMachine>& machines) {
  std::vector<std::pair<std::string, double>> values;
  for (const WorldMachine& m : machines) {
    for (size_t j = 0; j < m.model->joints().size(); ++j) {
      if (m.model->joints()[j].IsMoving()) {
        values.emplace_back(m.name + "_" + m.model->joints()[j].name, m.q[j]);
      }
    }
  }
  return JointStatesYaml(values, "edgefit world: sensor_msgs/JointState of cell.urdf as fitted "
                                 "(radians, metres)");
}

// Every file into `dir`, which exists and is empty.
Status WriteFiles(const std::vector<WorldMachine>& machines,
                  const std::vector<Eigen::Vector3f>* background,
                  const BackgroundOptions& background_options, const fs::path& dir,
                  std::vector<std::string>* names) {
  TriangleMesh as_scanned;
  std::vector<std::array<int32_t, 3>> voxels;
  if (background != nullptr) voxels = OccupiedVoxels(*background, background_options.voxel);
  for (const WorldMachine& m : machines) {
    const std::vector<Pose> T_world_link = m.model->ForwardKinematics(m.q, m.T_world_base);
    for (size_t l = 0; l < m.model->links().size(); ++l) {
      const Link& link = m.model->links()[l];
      const std::string name = m.name + "_" + link.name;
      TriangleMesh posed;  // its collision geometry as scanned
      if (!link.mesh.empty()) {
        const std::string file = MeshFile(name);
        EDGEFIT_RETURN_IF_ERROR(WriteBinaryStl((dir / file).string(), link.mesh, name));
        names->push_back(file);
        posed.Append(link.mesh, T_world_link[l]);
      }
      if (HasAttached(m, l)) {
        const std::string file = MeshFile(name, "_attached");
        EDGEFIT_RETURN_IF_ERROR(
            WriteBinaryStl((dir / file).string(), m.attached[l], name + " attached"));
        names->push_back(file);
        posed.Append(m.attached[l], T_world_link[l]);
      }
      as_scanned.Append(posed, Pose::Identity());
      if (background != nullptr) {
        CarveVoxels(posed, background_options.voxel, background_options.carve_margin, &voxels);
      }
    }
  }
  const std::vector<std::pair<std::string, std::string>> texts = {
      {"cell.urdf", CellUrdf(machines, false)},
      {"cell_frozen.urdf", CellUrdf(machines, true)},
      {"cell.srdf", CellSrdf(machines)},
      {"joint_states.yaml", CellJointStates(machines)}};
  for (const auto& [file, text] : texts) {
    EDGEFIT_RETURN_IF_ERROR(WriteStringAtomically((dir / file).string(), text));
    names->push_back(file);
  }
  EDGEFIT_RETURN_IF_ERROR(WriteMeshPly((dir / "machines_as_scanned.ply").string(), as_scanned,
                                       "edgefit world: the machines as fitted, world frame"));
  names->push_back("machines_as_scanned.ply");
  if (background == nullptr) return Status::Ok();
  return WriteBackground(voxels, background_options, dir.string(), names);
}

}  // namespace

Status WritePlanningWorld(const std::vector<WorldMachine>& machines,
                          const std::vector<Eigen::Vector3f>* background,
                          const BackgroundOptions& background_options, const std::string& folder,
                          std::vector<std::string>* written) {
  EDGEFIT_RETURN_IF_ERROR(CheckWorldMachines(machines));
  EDGEFIT_RETURN_IF_ERROR(CheckOutputFolder(folder));
  // Mimic and loop-closure joints as a consumer of the files computes them.
  std::vector<WorldMachine> resolved = machines;
  for (WorldMachine& m : resolved) {
    if (Status s = m.model->ResolveDependentJoints(&m.q); !s.ok()) {
      return Status::Error((m.source.empty() ? m.name : m.source) + ": " + s.message());
    }
  }
  const fs::path target = fs::absolute(folder).lexically_normal();
  const std::string pid = std::to_string(::getpid());
  const fs::path temporary = target.string() + ".tmp." + pid;
  const fs::path old = target.string() + ".old." + pid;
  std::error_code error;
  fs::remove_all(temporary, error);
  EDGEFIT_RETURN_IF_ERROR(CreateFolder((temporary / "meshes").string(), nullptr));
  std::vector<std::string> names;
  Status status = WriteFiles(resolved, background, background_options, temporary, &names);
  if (status.ok() && fs::exists(target)) {
    fs::rename(target, old, error);
    if (error) status = Status::Error(folder + ": cannot replace it: " + error.message());
  }
  if (status.ok()) {
    fs::rename(temporary, target, error);
    if (error) {
      fs::rename(old, target, error);  // put the old folder back
      status = Status::Error(folder + ": cannot write it: " + error.message());
    }
  }
  fs::remove_all(status.ok() ? old : temporary, error);
  if (!status.ok()) return status;
  if (written != nullptr) {
    for (const std::string& name : names) written->push_back((fs::path(folder) / name).string());
  }
  return Status::Ok();
}

}  // namespace edgefit
