#include "robot_bodies.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace edgefit {

Body MakeBody(const KinematicModel& model, int link, int joint) {
  Body body;
  body.link = link;
  body.joint = joint;
  std::vector<std::pair<int, Pose>> stack = {{link, Pose::Identity()}};
  while (!stack.empty()) {
    const auto [l, T] = stack.back();
    stack.pop_back();
    body.links.push_back(l);
    body.T_body_link.push_back(T);
    const std::vector<int>& children = model.links()[static_cast<size_t>(l)].child_joints;
    for (auto it = children.rbegin(); it != children.rend(); ++it) {  // URDF order out
      const Joint& j = model.joints()[static_cast<size_t>(*it)];
      if (j.type != JointType::kFixed) continue;
      stack.emplace_back(j.child_link, T * j.T_parent_child(0.0));
    }
  }
  return body;
}

std::vector<int> SubtreeLinks(const KinematicModel& model, int link) {
  std::vector<int> links;
  std::vector<int> stack = {link};
  while (!stack.empty()) {
    const int l = stack.back();
    stack.pop_back();
    links.push_back(l);
    const std::vector<int>& children = model.links()[static_cast<size_t>(l)].child_joints;
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      stack.push_back(model.joints()[static_cast<size_t>(*it)].child_link);
    }
  }
  return links;
}

Body MakeSubtree(const KinematicModel& model, int link, int joint,
                 const std::vector<Pose>& T_world_link) {
  Body body;
  body.link = link;
  body.joint = joint;
  body.links = SubtreeLinks(model, link);
  const Pose T_link_world = T_world_link[static_cast<size_t>(link)].inverse();
  for (const int l : body.links) {
    body.T_body_link.push_back(T_link_world * T_world_link[static_cast<size_t>(l)]);
  }
  return body;
}

void AppendBodySamples(const Body& body, const std::vector<SurfaceSamples>& link_samples,
                       const Pose& T_body_frame, SurfaceSamples* out) {
  for (size_t k = 0; k < body.links.size(); ++k) {
    const SurfaceSamples& s = link_samples[static_cast<size_t>(body.links[k])];
    const Pose T = T_body_frame * body.T_body_link[k];
    const Eigen::Matrix3f R = T.linear().cast<float>();
    const Eigen::Vector3f t = T.translation().cast<float>();
    for (size_t i = 0; i < s.points.size(); ++i) {
      out->points.push_back(R * s.points[i] + t);
      if (s.normals.size() == s.points.size()) out->normals.push_back(R * s.normals[i]);
      out->triangles.push_back(-1);  // not one mesh any more
    }
  }
}

void ThinSamples(int max_samples, SurfaceSamples* samples) {
  const size_t n = samples->points.size();
  if (max_samples <= 0 || n <= static_cast<size_t>(max_samples)) return;
  SurfaceSamples thin;
  const double stride = static_cast<double>(n) / max_samples;
  for (int k = 0; k < max_samples; ++k) {
    const size_t i = static_cast<size_t>(k * stride);
    thin.points.push_back(samples->points[i]);
    if (samples->normals.size() == n) thin.normals.push_back(samples->normals[i]);
    if (samples->triangles.size() == n) thin.triangles.push_back(samples->triangles[i]);
  }
  *samples = std::move(thin);
}

bool IsRotationallySymmetric(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body,
                             double min_share) {
  if (samples.points.empty()) return false;
  const Eigen::Vector3d a = axis_body.normalized();
  const Eigen::Vector3d u = a.unitOrthogonal(), v = a.cross(u);
  constexpr double kBin = 0.005;
  constexpr int kSectors = 12;
  std::map<std::pair<int64_t, int64_t>, std::pair<uint32_t, size_t>> rings;  // sectors, count
  for (const Eigen::Vector3f& pf : samples.points) {
    const Eigen::Vector3d p = pf.cast<double>();
    const double h = a.dot(p), x = u.dot(p), y = v.dot(p);
    const double r = std::hypot(x, y);
    const std::pair<int64_t, int64_t> key{static_cast<int64_t>(std::floor(r / kBin)),
                                          static_cast<int64_t>(std::floor(h / kBin))};
    int sector = static_cast<int>(std::floor((std::atan2(y, x) + M_PI) / (2.0 * M_PI) * kSectors));
    sector = std::min(std::max(sector, 0), kSectors - 1);
    auto& ring = rings[key];
    ring.first |= 1u << sector;
    ++ring.second;
  }
  size_t on_round = 0;
  for (const auto& [key, ring] : rings) {
    // Samples within a bin of the axis are round whatever their sectors.
    const bool round = key.first == 0 || __builtin_popcount(ring.first) >= 9;
    if (round) on_round += ring.second;
  }
  return static_cast<double>(on_round) >= min_share * static_cast<double>(samples.points.size());
}

}  // namespace edgefit
