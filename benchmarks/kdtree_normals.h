// The reference every speed figure of a fit is measured against: a plain
// kd-tree normal pass, what a point-cloud library computes before any
// registration starts. One nanoflann tree per scan over its valid points,
// a radius search and an unweighted PCA per point (the smallest
// eigenvector), in parallel over the points.
#ifndef EDGEFIT_BENCHMARKS_KDTREE_NORMALS_H_
#define EDGEFIT_BENCHMARKS_KDTREE_NORMALS_H_

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cstdint>
#include <utility>
#include <vector>

#include "edgefit/core/point_kdtree.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace bench {

// The valid points of `scan`, in its scanner frame: the cloud a library
// user would hand to a normal pass.
inline std::vector<Eigen::Vector3f> ValidPoints(const OrganizedScan& scan) {
  std::vector<Eigen::Vector3f> cloud;
  cloud.reserve(scan.size());
  for (size_t i = 0; i < scan.size(); ++i) {
    if (scan.IsValid(i)) cloud.push_back(scan.point_scanner(i));
  }
  return cloud;
}

// Normals of `cloud` from its neighbours within `radius` [m] (zero where
// fewer than 3); the tree is built inside, as a library user's call does.
inline std::vector<Eigen::Vector3f> KdTreeNormals(const std::vector<Eigen::Vector3f>& cloud,
                                                  float radius) {
  PointVectorAdaptor adaptor{&cloud};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<Eigen::Vector3f> normals(cloud.size(), Eigen::Vector3f::Zero());
#pragma omp parallel
  {
    std::vector<std::pair<uint32_t, float>> matches;
    const nanoflann::SearchParams params(32, 0.0f, false);
#pragma omp for schedule(dynamic, 1024)
    for (int64_t i = 0; i < static_cast<int64_t>(cloud.size()); ++i) {
      matches.clear();
      tree.radiusSearch(cloud[static_cast<size_t>(i)].data(), radius * radius, matches, params);
      if (matches.size() < 3) continue;
      const Eigen::Vector3f& p = cloud[static_cast<size_t>(i)];
      Eigen::Vector3f mean = Eigen::Vector3f::Zero();
      for (const auto& m : matches) mean += cloud[m.first] - p;
      mean /= static_cast<float>(matches.size());
      Eigen::Matrix3f cov = Eigen::Matrix3f::Zero();
      for (const auto& m : matches) {
        const Eigen::Vector3f d = cloud[m.first] - p - mean;
        cov.noalias() += d * d.transpose();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect(cov.cast<double>(), Eigen::ComputeEigenvectors);
      normals[static_cast<size_t>(i)] = solver.eigenvectors().col(0).cast<float>();
    }
  }
  return normals;
}

}  // namespace bench
}  // namespace edgefit

#endif  // EDGEFIT_BENCHMARKS_KDTREE_NORMALS_H_
