#include "solvers/base/up_direction.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/core/split_mix64.h"

namespace edgefit {
namespace {

// Every k-th valid point of every scan, about max_points in all.
std::vector<Eigen::Vector3d> SamplePoints(const ScanSet& scans, size_t max_points) {
  const size_t valid = scans.TotalValid();
  const size_t step = std::max<size_t>(1, valid / std::max<size_t>(1, max_points));
  std::vector<Eigen::Vector3d> points;
  points.reserve(valid / step + 1);
  size_t k = 0;
  for (const OrganizedScan& scan : scans.scans) {
    for (size_t i = 0; i < scan.size(); ++i) {
      if (scan.IsValid(i) && k++ % step == 0) points.push_back(scan.PointWorld(i));
    }
  }
  return points;
}

size_t CountInliers(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& n,
                    double offset, double distance, std::vector<size_t>* inliers) {
  if (inliers != nullptr) inliers->clear();
  size_t count = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (std::abs(n.dot(points[i]) - offset) <= distance) {
      ++count;
      if (inliers != nullptr) inliers->push_back(i);
    }
  }
  return count;
}

// The least-squares plane (normal, offset) of the points `indices`.
void FitPlane(const std::vector<Eigen::Vector3d>& points, const std::vector<size_t>& indices,
              Eigen::Vector3d* n, double* offset) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const size_t i : indices) mean += points[i];
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const size_t i : indices) scatter += (points[i] - mean) * (points[i] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  const Eigen::Vector3d fitted = eigen.eigenvectors().col(0);
  *n = fitted.dot(*n) < 0.0 ? Eigen::Vector3d(-fitted) : fitted;
  *offset = n->dot(mean);
}

}  // namespace

bool UpOptions::IsValid(std::string* error) const {
  const char* problem = nullptr;
  if (!(max_tilt > 0.0 && max_tilt < M_PI / 2)) problem = "max_tilt must be in (0, pi/2)";
  if (!(inlier_distance > 0.0)) problem = "inlier_distance must be > 0";
  if (!(min_share > 0.0 && min_share < 1.0)) problem = "min_share must be in (0, 1)";
  if (max_points < 3 || iterations < 1 || refinements < 0) {
    problem = "max_points >= 3, iterations >= 1 and refinements >= 0";
  }
  if (problem != nullptr && error != nullptr) *error = problem;
  return problem == nullptr;
}

Status EstimateUp(const ScanSet& scans, const UpOptions& options, UpEstimate* estimate) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("up: " + error);
  const std::vector<Eigen::Vector3d> points = SamplePoints(scans, options.max_points);
  if (points.size() < 3) return Status::Error("up: fewer than 3 valid points");
  const double min_cos = std::cos(options.max_tilt);
  SplitMix64 rng(options.seed);
  const int last = static_cast<int>(points.size()) - 1;
  size_t best = 0;
  Eigen::Vector3d best_n = Eigen::Vector3d::UnitZ();
  double best_offset = 0.0;
  for (int it = 0; it < options.iterations; ++it) {
    const Eigen::Vector3d& a = points[static_cast<size_t>(rng.Int(0, last))];
    const Eigen::Vector3d& b = points[static_cast<size_t>(rng.Int(0, last))];
    const Eigen::Vector3d& c = points[static_cast<size_t>(rng.Int(0, last))];
    Eigen::Vector3d n = (b - a).cross(c - a);
    const double norm = n.norm();
    if (!(norm > 1e-9)) continue;
    n /= norm;
    if (n.z() < 0.0) n = -n;
    if (n.z() < min_cos) continue;
    const size_t count = CountInliers(points, n, n.dot(a), options.inlier_distance, nullptr);
    if (count > best) {
      best = count;
      best_n = n;
      best_offset = n.dot(a);
    }
  }
  if (static_cast<double>(best) < options.min_share * static_cast<double>(points.size())) {
    return Status::Error("up: no plane within the tilt bound holds enough of the points");
  }
  std::vector<size_t> inliers;
  for (int round = 0; round < options.refinements; ++round) {
    CountInliers(points, best_n, best_offset, options.inlier_distance, &inliers);
    FitPlane(points, inliers, &best_n, &best_offset);
  }
  // The sensor sees the plane's upper side: up points from the plane to it.
  const Eigen::Vector3d sensor = scans.scans.front().T_world_scanner().translation();
  if (best_n.dot(sensor) - best_offset < 0.0) best_n = -best_n;
  // A plane through a steeper one's points (a strip of a floor beyond the
  // bound) refines to that one's normal: still a wall.
  if (std::abs(best_n.z()) < min_cos) {
    return Status::Error("up: no plane within the tilt bound holds enough of the points");
  }
  estimate->up = best_n;
  estimate->tilt = std::acos(std::clamp(best_n.z(), -1.0, 1.0));
  estimate->inliers = CountInliers(points, best_n, best_offset, options.inlier_distance, nullptr);
  estimate->sampled = points.size();
  return Status::Ok();
}

Eigen::Matrix3d LevellingRotation(const Eigen::Vector3d& up) {
  return Eigen::Quaterniond::FromTwoVectors(up.normalized(), Eigen::Vector3d::UnitZ())
      .toRotationMatrix();
}

}  // namespace edgefit
