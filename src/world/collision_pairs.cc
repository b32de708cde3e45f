#include "edgefit/world/collision_pairs.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <utility>

#include "edgefit/core/split_mix64.h"
#include "fcl_mesh.h"

namespace edgefit {
namespace {

// The links from `link` up to the root, `link` first.
std::vector<int> PathToRoot(const KinematicModel& model, int link) {
  std::vector<int> path = {link};
  while (model.links()[static_cast<size_t>(link)].parent_joint >= 0) {
    link = model.joints()[static_cast<size_t>(model.links()[static_cast<size_t>(link)].parent_joint)]
               .parent_link;
    path.push_back(link);
  }
  return path;
}

// A seeded posture within the limits, dependent joints resolved; false when
// its loop closures cannot be met.
bool SamplePosture(const KinematicModel& model, SplitMix64* rng, std::vector<double>* q) {
  *q = model.ZeroJoints();
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const Joint& joint = model.joints()[j];
    if (!joint.IsIndependent()) continue;
    (*q)[j] = joint.has_limits ? rng->Uniform(joint.lower, joint.upper) : rng->Uniform(-M_PI, M_PI);
  }
  return model.ResolveDependentJoints(q).ok();
}

}  // namespace

std::vector<std::pair<int, int>> TouchingLinks(const KinematicModel& a, const std::vector<Pose>& T_world_a,
                                               const KinematicModel& b, const std::vector<Pose>& T_world_b) {
  std::vector<std::pair<int, int>> touching;
  std::vector<std::unique_ptr<FclMesh>> meshes_b(b.links().size());
  for (size_t lb = 0; lb < b.links().size(); ++lb) {
    if (!b.links()[lb].mesh.empty()) meshes_b[lb] = std::make_unique<FclMesh>(b.links()[lb].mesh);
  }
  for (size_t la = 0; la < a.links().size(); ++la) {
    if (a.links()[la].mesh.empty()) continue;
    const Eigen::AlignedBox3d box_a = a.links()[la].mesh.BoundingBox(T_world_a[la]);
    std::unique_ptr<FclMesh> mesh_a;
    for (size_t lb = 0; lb < b.links().size(); ++lb) {
      if (!meshes_b[lb] || !box_a.intersects(b.links()[lb].mesh.BoundingBox(T_world_b[lb]))) continue;
      if (!mesh_a) mesh_a = std::make_unique<FclMesh>(a.links()[la].mesh);
      if (mesh_a->Collides(T_world_a[la], *meshes_b[lb], T_world_b[lb])) {
        touching.emplace_back(static_cast<int>(la), static_cast<int>(lb));
      }
    }
  }
  return touching;
}

bool MoveRelative(const KinematicModel& model, int link_a, int link_b) {
  const std::vector<int> a = PathToRoot(model, link_a);
  const std::vector<int> b = PathToRoot(model, link_b);
  const std::set<int> on_a(a.begin(), a.end());
  int common = -1;
  for (const int l : b) {
    if (on_a.count(l) != 0) {
      common = l;
      break;
    }
  }
  for (const std::vector<int>* path : {&a, &b}) {
    for (const int l : *path) {
      if (l == common) break;
      const Joint& joint = model.joints()[static_cast<size_t>(model.links()[static_cast<size_t>(l)].parent_joint)];
      if (joint.IsMoving()) return true;
    }
  }
  return false;
}

std::vector<LinkPair> DisabledCollisionPairs(const KinematicModel& model,
                                             const std::vector<double>& q_as_scanned,
                                             const CollisionPairsOptions& options) {
  std::vector<LinkPair> pairs;
  std::set<std::pair<int, int>> adjacent;
  for (const Joint& joint : model.joints()) {
    const int a = std::min(joint.parent_link, joint.child_link);
    const int b = std::max(joint.parent_link, joint.child_link);
    if (adjacent.insert({a, b}).second) pairs.push_back({a, b, "Adjacent"});
  }
  // The other pairs of links with meshes, and their hierarchies.
  const std::vector<Link>& links = model.links();
  std::vector<std::unique_ptr<FclMesh>> meshes(links.size());
  for (size_t l = 0; l < links.size(); ++l) {
    if (!links[l].mesh.empty()) meshes[l] = std::make_unique<FclMesh>(links[l].mesh);
  }
  std::vector<std::pair<int, int>> candidates;
  for (int a = 0; a < static_cast<int>(links.size()); ++a) {
    for (int b = a + 1; b < static_cast<int>(links.size()); ++b) {
      if (meshes[static_cast<size_t>(a)] && meshes[static_cast<size_t>(b)] &&
          adjacent.count({a, b}) == 0) {
        candidates.push_back({a, b});
      }
    }
  }
  const auto touching = [&](const std::vector<double>& q, std::vector<bool>* touch) {
    const std::vector<Pose> T = model.ForwardKinematics(q);
    for (size_t i = 0; i < candidates.size(); ++i) {
      const auto [a, b] = candidates[i];
      if (!(*touch)[i]) continue;
      (*touch)[i] = meshes[static_cast<size_t>(a)]->Collides(T[static_cast<size_t>(a)],
                                                             *meshes[static_cast<size_t>(b)],
                                                             T[static_cast<size_t>(b)]);
    }
  };
  std::vector<bool> as_scanned(candidates.size(), true);
  touching(q_as_scanned, &as_scanned);
  std::vector<bool> always = as_scanned;
  SplitMix64 rng(options.seed);
  std::vector<double> q;
  for (int s = 0; s < options.samples; ++s) {
    if (std::none_of(always.begin(), always.end(), [](bool t) { return t; })) break;
    if (SamplePosture(model, &rng, &q)) touching(q, &always);
  }
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (as_scanned[i]) pairs.push_back({candidates[i].first, candidates[i].second, always[i] ? "Always" : "Default"});
  }
  return pairs;
}

Status ReadDisabledCollisionPairs(const std::string& path, const KinematicModel& cell,
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


}  // namespace edgefit
