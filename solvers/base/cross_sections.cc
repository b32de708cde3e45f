#include "solvers/base/cross_sections.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "solvers/base/point_grid2.h"

namespace edgefit {

std::vector<Section> ScanSections(const ScanSet& scans, const std::vector<double>& heights,
                                  double max_edge, const Eigen::AlignedBox3d& crop_world) {
  std::vector<Section> sections(heights.size());
  for (size_t k = 0; k < heights.size(); ++k) sections[k].height = heights[k];
  const double max_edge2 = max_edge * max_edge;
  for (const OrganizedScan& scan : scans.scans) {
    if (!scan.organized()) continue;
    const int rows = scan.rows(), cols = scan.cols();
    // Per column, so that threads write their own buffers; joined in order.
    std::vector<std::vector<std::pair<int, Eigen::Vector2d>>> per_col(static_cast<size_t>(cols));
#pragma omp parallel for schedule(dynamic, 16)
    for (int col = 0; col < cols; ++col) {
      std::vector<std::pair<int, Eigen::Vector2d>>& out = per_col[static_cast<size_t>(col)];
      for (int row = 0; row < rows; ++row) {
        const size_t a = scan.Index(row, col);
        if (!scan.IsValid(a)) continue;
        const Eigen::Vector3d pa = scan.PointWorld(a);
        for (int side = 0; side < 2; ++side) {
          const int r2 = side == 0 ? row + 1 : row;
          const int c2 = side == 0 ? col : col + 1;
          if (r2 >= rows || c2 >= cols) continue;
          const size_t b = scan.Index(r2, c2);
          if (!scan.IsValid(b)) continue;
          const Eigen::Vector3d pb = scan.PointWorld(b);
          if ((pb - pa).squaredNorm() > max_edge2) continue;
          for (size_t k = 0; k < heights.size(); ++k) {
            const double h = heights[k];
            if ((pa.z() - h) * (pb.z() - h) >= 0.0 || pa.z() == pb.z()) continue;
            const double s = (h - pa.z()) / (pb.z() - pa.z());
            const Eigen::Vector3d p = pa + s * (pb - pa);
            if (!crop_world.isEmpty() && !crop_world.contains(p)) continue;
            out.emplace_back(static_cast<int>(k), p.head<2>());
          }
        }
      }
    }
    for (const auto& col_points : per_col) {
      for (const auto& kp : col_points) sections[static_cast<size_t>(kp.first)].points.push_back(kp.second);
    }
  }
  return sections;
}

std::vector<Section> MeshSections(const TriangleMesh& mesh, const std::vector<double>& heights,
                                  double spacing) {
  std::vector<Section> sections(heights.size());
  for (size_t k = 0; k < heights.size(); ++k) {
    Section& section = sections[k];
    section.height = heights[k];
    const double h = heights[k];
    for (const Eigen::Vector3i& t : mesh.triangles) {
      Eigen::Vector3d crossing[2];
      int n = 0;
      for (int e = 0; e < 3 && n < 2; ++e) {
        const Eigen::Vector3d& a = mesh.vertices[static_cast<size_t>(t[e])];
        const Eigen::Vector3d& b = mesh.vertices[static_cast<size_t>(t[(e + 1) % 3])];
        // Half-open rule: a vertex exactly at h counts on the upper side.
        const bool a_above = a.z() >= h, b_above = b.z() >= h;
        if (a_above == b_above) continue;
        crossing[n++] = a + (h - a.z()) / (b.z() - a.z()) * (b - a);
      }
      if (n != 2) continue;
      const double length = (crossing[1] - crossing[0]).norm();
      const int steps = std::max(1, static_cast<int>(std::ceil(length / spacing)));
      for (int i = 0; i <= steps; ++i) {
        const Eigen::Vector3d p = crossing[0] + (crossing[1] - crossing[0]) * (double(i) / steps);
        section.points.push_back(p.head<2>());
      }
    }
  }
  return sections;
}

std::vector<int> SectionCorners(const Section& section, const CornerOptions& options) {
  const std::vector<Eigen::Vector2d>& points = section.points;
  if (points.empty()) return {};
  const PointGrid2 grid(points, options.radius);
  std::vector<double> curvature(points.size(), -1.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d sum2 = Eigen::Matrix2d::Zero();
    int count = 0;
    grid.ForNeighbors(points[i], options.radius, [&](int j) {
      const Eigen::Vector2d& q = points[static_cast<size_t>(j)];
      sum += q;
      sum2 += q * q.transpose();
      ++count;
      return false;
    });
    if (count < options.min_neighbors) continue;
    const Eigen::Vector2d mean = sum / count;
    const Eigen::Matrix2d covariance = sum2 / count - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    const double l1 = std::max(0.0, eigen.eigenvalues()(0)), l0 = eigen.eigenvalues()(1);
    if (l0 + l1 > 0.0) curvature[i] = l1 / (l0 + l1);  // Eq. (7)
  }
  double sum = 0.0;
  int count = 0;
  for (const double c : curvature) {
    if (c >= 0.0) {
      sum += c;
      ++count;
    }
  }
  if (count == 0) return {};
  const double threshold = std::max(options.min_curvature, options.ratio_to_mean * sum / count);
  std::vector<int> candidates;
  for (size_t i = 0; i < points.size(); ++i) {
    if (curvature[i] > threshold) candidates.push_back(static_cast<int>(i));
  }
  // Highest curvature first; ties by index (deterministic).
  std::stable_sort(candidates.begin(), candidates.end(), [&](int a, int b) {
    return curvature[static_cast<size_t>(a)] > curvature[static_cast<size_t>(b)];
  });
  std::vector<int> corners;
  std::vector<Eigen::Vector2d> kept;
  for (const int i : candidates) {
    const Eigen::Vector2d& p = points[static_cast<size_t>(i)];
    bool near = false;
    for (const Eigen::Vector2d& k : kept) {
      if ((k - p).squaredNorm() < options.separation * options.separation) {
        near = true;
        break;
      }
    }
    if (near) continue;
    kept.push_back(p);
    corners.push_back(i);
  }
  return corners;
}

}  // namespace edgefit
