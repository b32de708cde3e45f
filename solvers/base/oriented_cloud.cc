#include "solvers/base/oriented_cloud.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "edgefit/core/point_kdtree.h"

namespace edgefit {
namespace {

struct VoxelSum {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  int scan = 0;  // the first scan that saw it (its scanner orients the normal)
};

}  // namespace

int64_t VoxelKey(const Eigen::Vector3d& p, double voxel) {
  const int64_t x = static_cast<int64_t>(std::floor(p.x() / voxel)) & 0x1fffff;
  const int64_t y = static_cast<int64_t>(std::floor(p.y() / voxel)) & 0x1fffff;
  const int64_t z = static_cast<int64_t>(std::floor(p.z() / voxel)) & 0x1fffff;
  return (x << 42) | (y << 21) | z;
}

bool OrientedCloudOptions::IsValid(std::string* error) const {
  if (!(voxel > 0.0)) *error = "voxel must be > 0";
  else if (!(normal_radius > 0.0)) *error = "normal_radius must be > 0";
  else if (min_neighbours < 3) *error = "min_neighbours must be >= 3";
  else if (!(min_planarity >= 0.0 && min_planarity < 1.0)) *error = "min_planarity must be in [0, 1)";
  else return true;
  return false;
}

OrientedCloud MakeOrientedCloud(const ScanSet& scans, const OrientedCloudOptions& options) {
  std::unordered_map<int64_t, VoxelSum> voxels;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    for (size_t i = 0; i < scan.size(); ++i) {
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d p = scan.PointWorld(i);
      if (!options.roi_world.isEmpty() && !options.roi_world.contains(p)) continue;
      VoxelSum& v = voxels[VoxelKey(p, options.voxel)];
      if (v.count == 0) v.scan = static_cast<int>(s);
      v.sum += p;
      ++v.count;
    }
  }
  // Voxel order: the keys sorted, whatever the hash table's order.
  std::vector<std::pair<int64_t, const VoxelSum*>> sorted;
  sorted.reserve(voxels.size());
  for (const auto& [key, v] : voxels) sorted.emplace_back(key, &v);
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::Vector3f> centroids(sorted.size());
  std::vector<int> seen_by(sorted.size());
  for (size_t k = 0; k < sorted.size(); ++k) {
    centroids[k] = (sorted[k].second->sum / sorted[k].second->count).cast<float>();
    seen_by[k] = sorted[k].second->scan;
  }
  OrientedCloud cloud;
  if (centroids.empty()) return cloud;
  PointVectorAdaptor adaptor{&centroids};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  const float radius_sq = static_cast<float>(options.normal_radius * options.normal_radius);
  const int n = static_cast<int>(centroids.size());
  std::vector<Eigen::Vector3f> normals(centroids.size(), Eigen::Vector3f::Zero());
#pragma omp parallel for schedule(dynamic, 256)
  for (int k = 0; k < n; ++k) {
    std::vector<std::pair<uint32_t, float>> found;
    tree.radiusSearch(centroids[static_cast<size_t>(k)].data(), radius_sq, found,
                      nanoflann::SearchParams(32, 0.0f, /*sorted=*/false));
    if (static_cast<int>(found.size()) < options.min_neighbours) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& f : found) mean += centroids[f.first].cast<double>();
    mean /= static_cast<double>(found.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& f : found) {
      const Eigen::Vector3d d = centroids[f.first].cast<double>() - mean;
      covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(covariance);
    const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
    if (!(lambda(1) > 0.0) || 1.0 - lambda(0) / lambda(1) < options.min_planarity) continue;
    Eigen::Vector3d normal = eig.eigenvectors().col(0);
    const Eigen::Vector3d origin =
        scans.scans[static_cast<size_t>(seen_by[static_cast<size_t>(k)])].T_world_scanner().translation();
    if (normal.dot(origin - centroids[static_cast<size_t>(k)].cast<double>()) < 0.0) normal = -normal;
    normals[static_cast<size_t>(k)] = normal.cast<float>();
  }
  for (size_t k = 0; k < centroids.size(); ++k) {
    if (normals[k].isZero()) continue;
    cloud.points.push_back(centroids[k]);
    cloud.normals.push_back(normals[k]);
  }
  return cloud;
}

}  // namespace edgefit
