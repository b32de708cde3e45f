#include "solvers/joints/body.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace edgefit {

bool CadSampleOptions::IsValid(std::string* error) const {
  if (!(icp_spacing > 0.0) || !(sweep_spacing > 0.0)) {
    if (error != nullptr) *error = "sample spacings must be > 0";
    return false;
  }
  if (!(max_model_extent > 0.0)) {
    if (error != nullptr) *error = "max_model_extent must be > 0";
    return false;
  }
  if (max_icp_samples < 100 || max_sweep_samples < 100 || max_subtree_icp_samples < 100 ||
      max_chain_samples < 100 || max_settling_chain_samples < 100) {
    if (error != nullptr) *error = "sample budgets must be >= 100";
    return false;
  }
  return true;
}

SurfaceSamples BodySamples(const Body& body, const std::vector<SurfaceSamples>& link_samples,
                           int max_samples) {
  SurfaceSamples samples;
  AppendBodySamples(body, link_samples, Pose::Identity(), &samples);
  ThinSamples(max_samples, &samples);
  return samples;
}

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

void AppendPosedSamples(const SurfaceSamples& samples, const Pose& T_out_samples,
                        SurfaceSamples* out) {
  const Eigen::Matrix3f R = T_out_samples.linear().cast<float>();
  const Eigen::Vector3f t = T_out_samples.translation().cast<float>();
  for (size_t i = 0; i < samples.points.size(); ++i) {
    out->points.push_back(R * samples.points[i] + t);
    if (samples.normals.size() == samples.points.size())
      out->normals.push_back(R * samples.normals[i]);
    out->triangles.push_back(-1);  // not one mesh any more
  }
}

void AppendBodySamples(const Body& body, const std::vector<SurfaceSamples>& link_samples,
                       const Pose& T_body_frame, SurfaceSamples* out) {
  for (size_t k = 0; k < body.links.size(); ++k) {
    AppendPosedSamples(link_samples[static_cast<size_t>(body.links[k])],
                       T_body_frame * body.T_body_link[k], out);
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

namespace {

// round[i]: sample i lies on a round ring about the axis (see the header).
std::vector<bool> OnRoundRings(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body) {
  const Eigen::Vector3d a = axis_body.normalized();
  const Eigen::Vector3d u = a.unitOrthogonal(), v = a.cross(u);
  constexpr double kBin = 0.005;
  constexpr int kSectors = 12;
  using Key = std::pair<int64_t, int64_t>;  // radius bin, height bin
  std::vector<Key> keys;
  keys.reserve(samples.points.size());
  std::map<Key, uint32_t> sectors;  // bit s: sector s holds a sample
  for (const Eigen::Vector3f& pf : samples.points) {
    const Eigen::Vector3d p = pf.cast<double>();
    const double h = a.dot(p), x = u.dot(p), y = v.dot(p);
    const double r = std::hypot(x, y);
    keys.emplace_back(static_cast<int64_t>(std::floor(r / kBin)),
                      static_cast<int64_t>(std::floor(h / kBin)));
    int sector = static_cast<int>(std::floor((std::atan2(y, x) + M_PI) / (2.0 * M_PI) * kSectors));
    sector = std::min(std::max(sector, 0), kSectors - 1);
    sectors[keys.back()] |= 1u << sector;
  }
  std::vector<bool> round(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    // Samples within a bin of the axis are round whatever their sectors.
    round[i] = keys[i].first == 0 || __builtin_popcount(sectors[keys[i]]) >= 9;
  }
  return round;
}

}  // namespace

bool IsRotationallySymmetric(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body,
                             double min_share) {
  if (samples.points.empty()) return false;
  const std::vector<bool> round = OnRoundRings(samples, axis_body);
  const size_t on_round = static_cast<size_t>(std::count(round.begin(), round.end(), true));
  return static_cast<double>(on_round) >= min_share * static_cast<double>(samples.points.size());
}

SurfaceSamples RoundPart(const SurfaceSamples& samples, const Eigen::Vector3d& axis_body) {
  const std::vector<bool> round = OnRoundRings(samples, axis_body);
  const size_t n = samples.points.size();
  SurfaceSamples out;
  for (size_t i = 0; i < n; ++i) {
    if (!round[i]) continue;
    out.points.push_back(samples.points[i]);
    if (samples.normals.size() == n) out.normals.push_back(samples.normals[i]);
    if (samples.triangles.size() == n) out.triangles.push_back(samples.triangles[i]);
  }
  return out;
}

}  // namespace edgefit
