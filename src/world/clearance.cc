#include "edgefit/world/clearance.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "edgefit/core/format.h"
#include "edgefit/io/joint_states.h"
#include "edgefit/model/urdf_loader.h"
#include "edgefit/world/background_voxels.h"
#include "edgefit/world/collision_pairs.h"
#include "fcl_mesh.h"

namespace edgefit {

namespace fs = std::filesystem;

bool ClearanceOptions::IsValid(std::string* error) const {
  if (!(step_rad > 0.0) || !std::isfinite(step_rad)) {
    *error = "step_rad must be > 0";
    return false;
  }
  if (!(step_m > 0.0) || !std::isfinite(step_m)) {
    *error = "step_m must be > 0";
    return false;
  }
  if (!(max_distance > 0.0) || !std::isfinite(max_distance)) {
    *error = "max_distance must be > 0";
    return false;
  }
  return true;
}

struct ClearanceWorld::Impl {
  KinematicModel cell;
  std::vector<double> q_scanned;
  std::vector<std::string> machines;
  std::string machine;                         // the one checked
  std::string prefix;                          // "<machine>_"
  std::vector<std::unique_ptr<FclMesh>> meshes;  // per cell link; null without a mesh
  std::string background_path;                 // background.bt; empty: none
  struct Sphere {
    int link;
    Eigen::Vector3d centre;  // link frame [m]
    double radius;           // [m], around the link's mesh
  };
  std::vector<Sphere> spheres;                 // of the moving links
  double max_distance = 0.0;                   // [m] the background's distances are capped at
  std::vector<int> moving;                     // machine links with meshes that move off its base
  std::vector<int> own;                        // machine links with meshes
  // Pairs (own link, other machine's link as scanned) that cell.srdf does
  // not disable.
  std::vector<std::tuple<int, int, Pose>> others;
  std::vector<std::pair<int, int>> self_pairs;
  std::map<std::string, int> joints;           // own joint name -> cell joint (independent)
  std::vector<std::string> joint_names;

  const std::string& LinkName(int l) const { return cell.links()[static_cast<size_t>(l)].name; }
  // Distances at one posture; with `first_only`, stops at the first contact.
  PostureClearance Measure(const std::vector<double>& q, bool first_only,
                           const FclMesh* background) const;
  // The box the moving links' spheres sweep over the states.
  Eigen::AlignedBox3d Reach(const std::vector<std::vector<double>>& states) const;
};

ClearanceWorld::ClearanceWorld() : impl_(std::make_unique<Impl>()) {}
ClearanceWorld::~ClearanceWorld() = default;

const std::vector<std::string>& ClearanceWorld::machines() const { return impl_->machines; }
const std::string& ClearanceWorld::machine() const { return impl_->machine; }

namespace {

std::string Join(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

// cell.srdf's <disable_collisions> pairs, as cell link indices (lower first).
Status ReadDisabledPairs(const std::string& path, const KinematicModel& cell,
                         std::set<std::pair<int, int>>* pairs) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    return Status::Error(path + ": cannot read it as XML (" + std::string(doc.ErrorStr()) + ")");
  }
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) return Status::Error(path + ": no <robot> element");
  for (const tinyxml2::XMLElement* e = robot->FirstChildElement("disable_collisions"); e != nullptr;
       e = e->NextSiblingElement("disable_collisions")) {
    const char* a = e->Attribute("link1");
    const char* b = e->Attribute("link2");
    const int la = a == nullptr ? -1 : cell.LinkIndex(a);
    const int lb = b == nullptr ? -1 : cell.LinkIndex(b);
    if (la < 0 || lb < 0) {
      return Status::Error(path + ": disable_collisions names a link that cell.urdf lacks ('" +
                           std::string(a == nullptr ? "" : a) + "', '" +
                           std::string(b == nullptr ? "" : b) + "')");
    }
    pairs->insert({std::min(la, lb), std::max(la, lb)});
  }
  return Status::Ok();
}

}  // namespace

Status ClearanceWorld::Load(const std::string& folder, const std::string& machine,
                            double max_distance) {
  Impl& w = *impl_;
  const fs::path dir(folder);
  if (!fs::is_directory(dir)) return Status::Error(folder + ": not a folder (an edgefit world)");
  EDGEFIT_RETURN_IF_ERROR(
      LoadKinematicModel((dir / "cell.urdf").string(), [] {
        ModelLoadOptions load;
        load.collision_geometry = true;  // the links' meshes and what rides on them
        return load;
      }(), &w.cell));
  const KinematicModel& cell = w.cell;
  const int world = cell.root_link();
  std::vector<int> roots;
  for (const int j : cell.links()[static_cast<size_t>(world)].child_joints) {
    const std::string& name = cell.joints()[static_cast<size_t>(j)].name;
    if (name.rfind("world_to_", 0) != 0) continue;
    w.machines.push_back(name.substr(9));
    roots.push_back(cell.joints()[static_cast<size_t>(j)].child_link);
  }
  const std::string list = Join(w.machines);
  const auto named = std::find(w.machines.begin(), w.machines.end(), machine);
  if (machine.empty() && w.machines.size() != 1) {
    return Status::Error(folder + ": " + std::to_string(w.machines.size()) + " machines (" + list +
                         "): name the one to check");
  }
  if (!machine.empty() && named == w.machines.end()) {
    return Status::Error(folder + ": no machine '" + machine + "' (the world holds: " +
                         (list.empty() ? "none" : list) + ")");
  }
  const size_t index = machine.empty() ? 0 : static_cast<size_t>(named - w.machines.begin());
  const int root = roots[index];
  w.machine = w.machines[index];
  w.prefix = w.machine + "_";

  // As scanned: joint_states.yaml's values.
  const std::string states_path = (dir / "joint_states.yaml").string();
  std::vector<std::pair<std::string, double>> states;
  EDGEFIT_RETURN_IF_ERROR(ReadJointStates(states_path, &states));
  w.q_scanned = cell.ZeroJoints();
  for (const auto& [name, value] : states) {
    const int j = cell.JointIndex(name);
    if (j < 0) return Status::Error(states_path + ": joint '" + name + "' is not in cell.urdf");
    w.q_scanned[static_cast<size_t>(j)] = value;
  }
  if (Status s = cell.ResolveDependentJoints(&w.q_scanned); !s.ok()) {
    return Status::Error(states_path + ": " + s.message());
  }
  std::set<std::pair<int, int>> disabled;
  EDGEFIT_RETURN_IF_ERROR(ReadDisabledPairs((dir / "cell.srdf").string(), cell, &disabled));

  // The machine's links: the subtree under its base; which move off it.
  std::vector<bool> in_machine(cell.links().size(), false), fixed_to_base(cell.links().size(), false);
  in_machine[static_cast<size_t>(root)] = fixed_to_base[static_cast<size_t>(root)] = true;
  for (const int j : cell.joint_order()) {
    const Joint& joint = cell.joints()[static_cast<size_t>(j)];
    if (!in_machine[static_cast<size_t>(joint.parent_link)]) continue;
    in_machine[static_cast<size_t>(joint.child_link)] = true;
    fixed_to_base[static_cast<size_t>(joint.child_link)] =
        fixed_to_base[static_cast<size_t>(joint.parent_link)] && !joint.IsMoving();
    if (joint.IsIndependent()) {
      const std::string own = joint.name.substr(w.prefix.size());
      w.joints[own] = j;
      w.joint_names.push_back(own);
    }
  }
  const std::vector<Pose> T_scanned = cell.ForwardKinematics(w.q_scanned);
  w.meshes.resize(cell.links().size());
  for (size_t l = 0; l < cell.links().size(); ++l) {
    if (cell.links()[l].mesh.empty()) continue;
    w.meshes[l] = std::make_unique<FclMesh>(cell.links()[l].mesh);
    const int li = static_cast<int>(l);
    if (in_machine[l]) {
      w.own.push_back(li);
      if (!fixed_to_base[l]) w.moving.push_back(li);
    }
  }
  for (const int l : w.own) {
    for (size_t o = 0; o < cell.links().size(); ++o) {
      const int oi = static_cast<int>(o);
      if (!in_machine[o] && w.meshes[o] && disabled.count({std::min(l, oi), std::max(l, oi)}) == 0) {
        w.others.emplace_back(l, oi, T_scanned[o]);
      }
    }
  }
  for (size_t i = 0; i < w.own.size(); ++i) {
    for (size_t k = i + 1; k < w.own.size(); ++k) {
      const int a = std::min(w.own[i], w.own[k]), b = std::max(w.own[i], w.own[k]);
      if (disabled.count({a, b}) == 0 && MoveRelative(cell, a, b)) w.self_pairs.push_back({a, b});
    }
  }
  // The background: background.bt, read by Check where the postures reach.
  if (fs::exists(dir / "background.bt")) w.background_path = (dir / "background.bt").string();
  for (const int l : w.moving) {
    const TriangleMesh& mesh = cell.links()[static_cast<size_t>(l)].mesh;
    const Eigen::Vector3d centre = mesh.BoundingBox(Pose::Identity()).center();
    double radius = 0.0;
    for (const Eigen::Vector3d& v : mesh.vertices) radius = std::max(radius, (v - centre).norm());
    w.spheres.push_back({l, centre, radius});
  }
  w.max_distance = max_distance;
  return Status::Ok();
}

Status ClearanceWorld::Posture(const std::vector<std::pair<std::string, double>>& values,
                               std::vector<double>* q_cell) const {
  const Impl& w = *impl_;
  *q_cell = w.q_scanned;
  for (const auto& [name, value] : values) {
    const auto it = w.joints.find(name);
    if (it == w.joints.end()) {
      const int j = w.cell.JointIndex(w.prefix + name);
      return Status::Error("joint '" + name + "': " +
                           (j >= 0 ? "set by the joints it follows (mimic or loop closure)"
                                   : "not a joint of " + w.machine + " (" + Join(w.joint_names) + ")"));
    }
    const Joint& joint = w.cell.joints()[static_cast<size_t>(it->second)];
    if (!std::isfinite(value)) return Status::Error("joint '" + name + "': value not finite");
    if (joint.has_limits && (value < joint.lower - 1e-9 || value > joint.upper + 1e-9)) {
      return Status::Error("joint '" + name + "': " + FormatNumber("%.6g", value) + " is outside its limits [" +
                           FormatNumber("%.6g", joint.lower) + ", " + FormatNumber("%.6g", joint.upper) + "]");
    }
    (*q_cell)[static_cast<size_t>(it->second)] = value;
  }
  return w.cell.ResolveDependentJoints(q_cell);
}

Eigen::AlignedBox3d ClearanceWorld::Impl::Reach(const std::vector<std::vector<double>>& states) const {
  Eigen::AlignedBox3d box;
  for (const std::vector<double>& q : states) {
    const std::vector<Pose> T = cell.ForwardKinematics(q);
    for (const Sphere& s : spheres) {
      const Eigen::Vector3d c = T[static_cast<size_t>(s.link)] * s.centre;
      box.extend(c - Eigen::Vector3d::Constant(s.radius));
      box.extend(c + Eigen::Vector3d::Constant(s.radius));
    }
  }
  return box;
}

PostureClearance ClearanceWorld::Impl::Measure(const std::vector<double>& q, bool first_only,
                                               const FclMesh* background) const {
  PostureClearance c;
  const std::vector<Pose> T = cell.ForwardKinematics(q);
  const auto pose = [&](int l) -> const Pose& { return T[static_cast<size_t>(l)]; };
  const auto mesh = [&](int l) -> const FclMesh& { return *meshes[static_cast<size_t>(l)]; };
  // Takes d for *slot; the first contact names the pair. True to stop.
  const auto take = [&](double* slot, int a, int b, const FclMesh& mb, const Pose& Tb) {
    const double d = first_only ? (mesh(a).Collides(pose(a), mb, Tb) ? 0.0 : PostureClearance::kNone)
                                : mesh(a).Distance(pose(a), mb, Tb);
    *slot = std::min(*slot, d);
    if (d > 0.0 || c.colliding) return false;
    c.colliding = true;
    mesh(a).Collides(pose(a), mb, Tb, &c.p_world_collision);
    c.collision_a = LinkName(a);
    c.collision_b = b < 0 ? "background" : LinkName(b);
    return first_only;
  };
  if (!background_path.empty()) c.distance_to_background = max_distance;
  if (background != nullptr) {
    for (const int l : moving) {
      if (take(&c.distance_to_background, l, -1, *background, Pose::Identity())) return c;
    }
  }
  for (const auto& [l, o, To] : others) {
    if (take(&c.distance_to_machines, l, o, mesh(o), To)) return c;
  }
  for (const auto& [a, b] : self_pairs) {
    if (take(&c.self_distance, a, b, mesh(b), pose(b))) return c;
  }
  return c;
}

std::vector<PostureClearance> ClearanceWorld::Check(const std::vector<std::vector<double>>& waypoints,
                                                    const ClearanceOptions& options, Status* status) const {
  const Impl& w = *impl_;
  *status = Status::Ok();
  // The states on the way to each waypoint (after the first), the steps
  // apart, with their fraction of the way.
  std::vector<std::vector<std::pair<double, std::vector<double>>>> ways(waypoints.size());
  std::vector<std::vector<double>> states = waypoints;
  for (size_t k = 1; k < waypoints.size(); ++k) {
    const std::vector<double>& from = waypoints[k - 1];
    const std::vector<double>& to = waypoints[k];
    int count = 1;
    for (const auto& [name, j] : w.joints) {
      const Joint& joint = w.cell.joints()[static_cast<size_t>(j)];
      const double step = joint.type == JointType::kPrismatic ? options.step_m : options.step_rad;
      const double move = std::abs(to[static_cast<size_t>(j)] - from[static_cast<size_t>(j)]);
      count = std::max(count, static_cast<int>(std::ceil(move / step)));
    }
    std::vector<double> q = from;
    for (int i = 1; i < count; ++i) {
      const double t = static_cast<double>(i) / count;
      for (const auto& [name, j] : w.joints) {
        const size_t js = static_cast<size_t>(j);
        q[js] = from[js] + t * (to[js] - from[js]);
      }
      (void)w.cell.ResolveDependentJoints(&q);  // best values kept when a closure is missed
      ways[k].emplace_back(t, q);
      states.push_back(q);
    }
  }
  // The background where the moving links go, grown by max_distance.
  std::unique_ptr<FclMesh> background;
  if (!w.background_path.empty()) {
    Eigen::AlignedBox3d region = w.Reach(states);
    if (!region.isEmpty()) {
      region.min().array() -= options.max_distance;
      region.max().array() += options.max_distance;
      std::vector<std::array<int32_t, 3>> voxels;
      double voxel = 0.0;
      *status = ReadBackgroundVoxels(w.background_path, region, &voxels, &voxel);
      if (!status->ok()) return {};
      if (!voxels.empty()) background = std::make_unique<FclMesh>(VoxelUnionSurface(voxels, voxel));
    }
  }
  std::vector<PostureClearance> out;
  for (size_t k = 0; k < waypoints.size(); ++k) {
    PostureClearance at = w.Measure(waypoints[k], /*first_only=*/false, background.get());
    at.collision_fraction = at.colliding ? 1.0 : 0.0;
    for (const auto& [t, q] : ways[k]) {
      const PostureClearance on_way = w.Measure(q, /*first_only=*/true, background.get());
      if (!on_way.colliding) continue;
      at.colliding = true;
      at.collision_fraction = t;
      at.collision_a = on_way.collision_a;
      at.collision_b = on_way.collision_b;
      at.p_world_collision = on_way.p_world_collision;
      break;
    }
    out.push_back(at);
  }
  return out;
}

}  // namespace edgefit
