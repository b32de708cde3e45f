#include "edgefit/model/surface_sampler.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "edgefit/core/split_mix64.h"

namespace edgefit {
namespace {

}  // namespace

bool SamplingOptions::IsValid(std::string* error) const {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    *error = "spacing must be a positive number of metres";
    return false;
  }
  return true;
}

SurfaceSamples SampleMeshSurface(const TriangleMesh& mesh, double spacing, uint64_t seed) {
  CHECK_GT(spacing, 0.0) << "see SamplingOptions::IsValid";
  SurfaceSamples out;
  const size_t num_triangles = mesh.triangles.size();
  std::vector<double> cumulative_area(num_triangles);
  std::vector<Eigen::Vector3d> normals(num_triangles);
  double total = 0.0;
  for (size_t t = 0; t < num_triangles; ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d cross = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
    const double norm = cross.norm();
    total += 0.5 * norm;
    cumulative_area[t] = total;
    normals[t] = norm > 0.0 ? Eigen::Vector3d(cross / norm) : Eigen::Vector3d::Zero();
  }
  if (!(total > 0.0)) return out;
  const size_t count =
      std::max<size_t>(1, static_cast<size_t>(std::llround(total / (spacing * spacing))));
  out.points.reserve(count);
  out.normals.reserve(count);
  out.triangles.reserve(count);
  SplitMix64 rng(seed);
  for (size_t i = 0; i < count; ++i) {
    const double u = (static_cast<double>(i) + rng.Uniform()) / static_cast<double>(count) * total;
    // First triangle whose cumulative area exceeds u: zero-area triangles
    // are never chosen.
    size_t t = std::upper_bound(cumulative_area.begin(), cumulative_area.end(), u) -
               cumulative_area.begin();
    t = std::min(t, num_triangles - 1);
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    // Uniform on the triangle: s = sqrt(r1), p = a + s (1 - r2) (b - a) + s r2 (c - a).
    const double s = std::sqrt(rng.Uniform());
    const double r2 = rng.Uniform();
    const Eigen::Vector3d p = a + s * (1.0 - r2) * (b - a) + s * r2 * (c - a);
    out.points.push_back(p.cast<float>());
    out.normals.push_back(normals[t].cast<float>());
    out.triangles.push_back(static_cast<int>(t));
  }
  return out;
}

std::vector<SurfaceSamples> SampleModelSurfaces(const KinematicModel& model,
                                                const SamplingOptions& options) {
  const int num_links = static_cast<int>(model.links().size());
  std::vector<SurfaceSamples> out(num_links);
#pragma omp parallel for schedule(dynamic)
  for (int l = 0; l < num_links; ++l) {
    out[l] = SampleMeshSurface(model.links()[l].mesh, options.spacing,
                               SplitMix64::StreamSeed(options.seed, static_cast<uint64_t>(l)));
  }
  return out;
}

}  // namespace edgefit
