#include "surface_clearance.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "edgefit/model/surface_sampler.h"

namespace edgefit {
namespace scene_internal {
namespace {

SurfaceCloud SampleCloud(const TriangleMesh& mesh, const Pose& T_world_mesh, double min_spacing,
                         int max_samples, uint64_t seed) {
  SurfaceCloud cloud;
  if (mesh.empty()) return cloud;
  cloud.area = mesh.SurfaceArea();
  const double spacing = std::max(min_spacing, std::sqrt(cloud.area / max_samples));
  const SurfaceSamples samples = SampleMeshSurface(mesh, spacing, seed);
  for (size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3d n = T_world_mesh.linear() * samples.normals[i].cast<double>();
    if (!n.allFinite() || n.squaredNorm() < 0.5) continue;  // degenerate face
    cloud.p_world.push_back(T_world_mesh * samples.points[i].cast<double>());
    cloud.n_world.push_back(n);
    cloud.box_world.extend(cloud.p_world.back());
  }
  return cloud;
}

}  // namespace

SurfaceClearance::SurfaceClearance(const KinematicModel& model,
                                   const std::vector<Pose>& T_world_link, double min_spacing,
                                   int max_samples, uint64_t seed)
    : min_spacing_(min_spacing), max_samples_(max_samples) {
  CHECK_EQ(T_world_link.size(), model.links().size());
  CHECK_GT(min_spacing, 0.0);
  CHECK_GT(max_samples, 0);
  for (size_t k = 0; k < model.links().size(); ++k) {
    clouds_.push_back(SampleCloud(model.links()[k].mesh, T_world_link[k], min_spacing,
                                  max_samples, seed + k));
    clouds_.back().link = static_cast<int>(k);
  }
}

void SurfaceClearance::AddObstacle(const TriangleMesh& mesh_world, uint64_t seed) {
  clouds_.push_back(SampleCloud(mesh_world, Pose::Identity(), min_spacing_, max_samples_, seed));
}

double SurfaceClearance::Clearance(const Eigen::Vector3d& p_world, double reach,
                                   Eigen::Vector3d* normal) const {
  double best = std::numeric_limits<double>::infinity();
  for (const SurfaceCloud& cloud : clouds_) {
    if (cloud.p_world.empty() || cloud.box_world.exteriorDistance(p_world) > reach) continue;
    size_t nearest = 0;
    double nearest_d2 = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < cloud.p_world.size(); ++i) {
      const double d2 = (cloud.p_world[i] - p_world).squaredNorm();
      if (d2 < nearest_d2) {
        nearest_d2 = d2;
        nearest = i;
      }
    }
    const double signed_distance = (p_world - cloud.p_world[nearest]).dot(cloud.n_world[nearest]);
    if (signed_distance < best) {
      best = signed_distance;
      if (normal != nullptr) *normal = cloud.n_world[nearest];
    }
  }
  return best;
}

Eigen::Vector3d SurfaceClearance::PushOut(const Eigen::Vector3d& p_world, double wanted) const {
  Eigen::Vector3d p = p_world;
  // Each round fixes the worst surface; 8 rounds settle a point wedged
  // between two or three overlapping link housings.
  for (int round = 0; round < 8; ++round) {
    Eigen::Vector3d n;
    const double clearance = Clearance(p, wanted + 0.05, &n);
    if (!(clearance < wanted)) break;
    // 0.5 mm extra so that sample noise does not leave it just short.
    p += (wanted - clearance + 5e-4) * n;
  }
  return p;
}

}  // namespace scene_internal
}  // namespace edgefit
