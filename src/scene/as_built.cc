#include "edgefit/scene/as_built.h"

#include <cmath>
#include <algorithm>
#include <map>
#include <utility>

#include "edgefit/core/random_unit.h"

namespace edgefit {
namespace {

double LongestEdge(const TriangleMesh& mesh) {
  double longest = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      longest = std::max(longest, (mesh.vertices[t[e]] - mesh.vertices[t[(e + 1) % 3]]).norm());
    }
  }
  return longest;
}

}  // namespace

bool AsBuiltOptions::IsValid(std::string* error) const {
  if (!(amplitude_min >= 0.0 && amplitude_min <= amplitude_max && amplitude_max < 0.05)) {
    *error = "as-built amplitude must satisfy 0 <= min <= max < 50 mm";
  } else if (!(wavelength_min > 0.0 && wavelength_min <= wavelength_max)) {
    *error = "as-built wavelengths must satisfy 0 < min <= max";
  } else if (!(max_edge > 0.0) || max_triangles < 1) {
    *error = "as-built max_edge and max_triangles must be positive";
  } else {
    return true;
  }
  return false;
}

AsBuiltField::AsBuiltField(const AsBuiltOptions& options, int link) {
  SplitMix64 rng = SplitMix64::Stream(options.seed, static_cast<uint64_t>(link) + 1);
  amplitude_ = rng.Uniform(options.amplitude_min, options.amplitude_max);
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double wavelength = rng.Uniform(options.wavelength_min, options.wavelength_max);
    wave_[k] = RandomUnitVector(&rng) * (2.0 * M_PI / wavelength);
    direction_[k] = RandomUnitVector(&rng);
    weight_[k] = rng.Uniform(0.5, 1.0);
    phase_[k] = rng.Uniform(0.0, 2.0 * M_PI);
    sum += weight_[k];
  }
  for (double& w : weight_) w /= sum;
}

Eigen::Vector3d AsBuiltField::Displacement(const Eigen::Vector3d& x_link) const {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) d += weight_[k] * std::sin(wave_[k].dot(x_link) + phase_[k]) * direction_[k];
  return amplitude_ * d;
}

void SubdivideMesh(double max_edge, int max_triangles, TriangleMesh* mesh) {
  while (LongestEdge(*mesh) > max_edge &&
         4 * mesh->triangles.size() <= static_cast<size_t>(max_triangles)) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      const int index = static_cast<int>(mesh->vertices.size());
      mesh->vertices.push_back(0.5 * (mesh->vertices[a] + mesh->vertices[b]));
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Eigen::Vector3i> split;
    split.reserve(4 * mesh->triangles.size());
    for (const Eigen::Vector3i& t : mesh->triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      split.emplace_back(t[0], ab, ca);
      split.emplace_back(ab, t[1], bc);
      split.emplace_back(ca, bc, t[2]);
      split.emplace_back(ab, bc, ca);
    }
    mesh->triangles = std::move(split);
  }
}

void ApplyAsBuilt(const AsBuiltOptions& options, int link, const Pose& T_world_link,
                  TriangleMesh* mesh_world) {
  SubdivideMesh(options.max_edge, options.max_triangles, mesh_world);
  const AsBuiltField field(options, link);
  const Pose T_link_world = T_world_link.inverse();
  for (Eigen::Vector3d& v : mesh_world->vertices) {
    v += T_world_link.linear() * field.Displacement(T_link_world * v);
  }
}

}  // namespace edgefit
