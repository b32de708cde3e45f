#include "edgefit/world/clearance.h"

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
#include "clearance_impl.h"
#include "fcl_mesh.h"
#include "least_distance.h"

namespace edgefit {

namespace fs = std::filesystem;

bool ClearanceOptions::IsValid(std::string* error) const {
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  const char* bad = !positive(step_rad)       ? "step_rad must be > 0"
                    : !positive(step_m)       ? "step_m must be > 0"
                    : !positive(max_distance) ? "max_distance must be > 0"
                                              : nullptr;
  if (bad != nullptr) *error = bad;
  return bad == nullptr;
}

std::string DescribeCollision(const PostureClearance& c) {
  if (!c.colliding) return "";
  std::string text = c.collision_a + " with " + c.collision_b +
                     FormatNumber(" at (%.3f", c.p_world_collision.x()) +
                     FormatNumber(", %.3f", c.p_world_collision.y()) +
                     FormatNumber(", %.3f) m", c.p_world_collision.z());
  if (c.collision_fraction < 1.0) {
    text += FormatNumber(" (%.0f %% of the way from the previous waypoint)", 100.0 * c.collision_fraction);
  }
  return text;
}

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
  EDGEFIT_RETURN_IF_ERROR(ReadDisabledCollisionPairs((dir / "cell.srdf").string(), cell, &disabled));

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
  w.spheres.resize(cell.links().size());
  for (size_t l = 0; l < cell.links().size(); ++l) {
    const TriangleMesh& mesh = cell.links()[l].mesh;
    if (mesh.empty()) continue;
    Impl::Sphere& s = w.spheres[l];
    s.centre = mesh.BoundingBox(Pose::Identity()).center();
    for (const Eigen::Vector3d& v : mesh.vertices) s.radius = std::max(s.radius, (v - s.centre).norm());
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
    for (const int l : moving) {
      const Sphere& s = spheres[static_cast<size_t>(l)];
      const Eigen::Vector3d c = T[static_cast<size_t>(l)] * s.centre;
      box.extend(c - Eigen::Vector3d::Constant(s.radius));
      box.extend(c + Eigen::Vector3d::Constant(s.radius));
    }
  }
  return box;
}

PostureClearance ClearanceWorld::Impl::Measure(const std::vector<double>& q, bool first_only,
                                               const FclMesh* background, Previous* previous) const {
  PostureClearance c;
  const std::vector<Pose> T = cell.ForwardKinematics(q);
  const auto pose = [&](int l) -> const Pose& { return T[static_cast<size_t>(l)]; };
  const auto mesh = [&](int l) -> const FclMesh* { return meshes[static_cast<size_t>(l)].get(); };
  // How far any point of the machine's links moved since the previous
  // posture: each least distance is at most the previous one plus this
  // (twice between two of its links), where its search starts.
  double moved = PostureClearance::kNone;
  if (previous != nullptr && !previous->T.empty()) {
    moved = 0.0;
    for (const int l : own) {
      const Pose& a = T[static_cast<size_t>(l)];
      const Pose& b = previous->T[static_cast<size_t>(l)];
      const Sphere& s = spheres[static_cast<size_t>(l)];
      const double turn = Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle();
      moved = std::max(moved, (a * s.centre - b * s.centre).norm() + turn * s.radius);
    }
  }
  const auto first_cap = [&](double PostureClearance::*distance, double factor) {
    const double last = std::isfinite(moved) ? previous->clearance.*distance : PostureClearance::kNone;
    return std::isfinite(last) ? last + factor * moved : PostureClearance::kNone;
  };
  const auto pair = [&](int a, int b, const FclMesh* mb, const Pose* Tb, int cache) {
    const Sphere& sa = spheres[static_cast<size_t>(a)];
    MeshPair p{0.0, a, b, mesh(a), &pose(a), mb, Tb, cache, sa.centre, sa.radius};
    if (b >= 0) {
      const Sphere& sb = spheres[static_cast<size_t>(b)];
      p.bound = std::max(0.0, (pose(a) * sa.centre - *Tb * sb.centre).norm() - sa.radius - sb.radius);
    }
    return p;
  };
  // Each distance for *slot; the first contact names the pair. True to stop
  // (first_only and a contact).
  const auto take = [&](double* slot, const std::vector<MeshPair>& pairs, double cap, PairCache* cache) {
    const LeastDistance least = first_only ? FindContact(pairs) : FindLeastDistance(pairs, *slot, cap, cache);
    *slot = std::min(*slot, least.distance);
    if (least.contact && !c.colliding) {
      c.colliding = true;
      c.collision_a = LinkName(least.contact_a);
      c.collision_b = least.contact_b < 0 ? "background" : LinkName(least.contact_b);
      c.p_world_collision = least.p_world;
    }
    return first_only && c.colliding;
  };
  const Pose identity = Pose::Identity();
  PairCache* cache = previous != nullptr ? &previous->pairs : nullptr;
  int slot = 0;  // the pairs' cache slots: background, other machines, self (PairSlots)
  std::vector<MeshPair> pairs;
  if (!background_path.empty()) c.distance_to_background = max_distance;
  if (background != nullptr) {
    for (const int l : moving) pairs.push_back(pair(l, -1, background, &identity, slot++));
    if (take(&c.distance_to_background, pairs, first_cap(&PostureClearance::distance_to_background, 1.0), cache)) {
      return c;
    }
  }
  slot = static_cast<int>(moving.size());
  pairs.clear();
  for (const auto& [l, o, To] : others) pairs.push_back(pair(l, o, mesh(o), &To, slot++));
  if (take(&c.distance_to_machines, pairs, first_cap(&PostureClearance::distance_to_machines, 1.0), cache)) {
    return c;
  }
  pairs.clear();
  for (const auto& [a, b] : self_pairs) pairs.push_back(pair(a, b, mesh(b), &pose(b), slot++));
  take(&c.self_distance, pairs, first_cap(&PostureClearance::self_distance, 2.0), cache);
  if (previous != nullptr) {
    previous->T = T;
    previous->clearance = c;
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
      if (!voxels.empty()) background = std::make_unique<FclMesh>(VoxelUnionRectangles(voxels, voxel));
    }
  }
  // The waypoints in runs of kRun, shared among the threads (FCL's queries
  // only read). In a run, the previous waypoint bounds where the next one's
  // searches start, and a pair of links that kept its relative pose keeps
  // its distance: what a waypoint gets depends on its run only, not on the
  // threads.
  constexpr int64_t kRun = 64;
  std::vector<PostureClearance> out(waypoints.size());
  const int64_t count = static_cast<int64_t>(waypoints.size());
#pragma omp parallel
  {
    Impl::Previous previous;
#pragma omp for schedule(static, kRun)
  for (int64_t i = 0; i < count; ++i) {
    const size_t k = static_cast<size_t>(i);
    if (i % kRun == 0) previous = {{}, {}, PairCache(w.PairSlots())};
    PostureClearance& at = out[k];
    at = w.Measure(waypoints[k], /*first_only=*/false, background.get(), &previous);
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
  }
  }
  return out;
}

}  // namespace edgefit
