#include "edgefit/scanner/edge_proximity.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace edgefit {
namespace {

// 21 bits per axis: +/- 2^20 cells of 6 mm cover +/- 6 km around the origin.
constexpr int64_t kAxisOffset = int64_t{1} << 20;
constexpr int64_t kAxisMask = (int64_t{1} << 21) - 1;

}  // namespace

double PointSegmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                            const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  double t = length2 > 0.0 ? (p - a).dot(ab) / length2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return (a + t * ab - p).norm();
}

EdgeProximityIndex::EdgeProximityIndex(std::vector<EdgeSegment> segments, double radius)
    : segments_(std::move(segments)), radius_(radius) {
  CHECK_GT(radius, 0.0);
  cell_size_ = 4.0 * radius;
  if (segments_.empty()) return;
  // Cells are counted from the lower corner of the segments' box, so keys
  // stay small whatever the world coordinates.
  Eigen::AlignedBox3d box;
  for (const EdgeSegment& s : segments_) {
    box.extend(s.a);
    box.extend(s.b);
  }
  origin_ = box.min() - Eigen::Vector3d::Constant(cell_size_);

  // (key, segment) pairs, then grouped by key into a flat array.
  std::vector<std::pair<uint64_t, uint32_t>> entries;
  for (size_t i = 0; i < segments_.size(); ++i) {
    const EdgeSegment& s = segments_[i];
    const double length = (s.b - s.a).norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / cell_size_)));
    for (int k = 0; k < pieces; ++k) {
      const Eigen::Vector3d p0 = s.a + (s.b - s.a) * (static_cast<double>(k) / pieces);
      const Eigen::Vector3d p1 = s.a + (s.b - s.a) * (static_cast<double>(k + 1) / pieces);
      const Eigen::Vector3d lo = p0.cwiseMin(p1) - Eigen::Vector3d::Constant(radius_) - origin_;
      const Eigen::Vector3d hi = p0.cwiseMax(p1) + Eigen::Vector3d::Constant(radius_) - origin_;
      const Eigen::Vector3d c0 = (lo / cell_size_).array().floor();
      const Eigen::Vector3d c1 = (hi / cell_size_).array().floor();
      for (int64_t ix = static_cast<int64_t>(c0.x()); ix <= static_cast<int64_t>(c1.x()); ++ix) {
        for (int64_t iy = static_cast<int64_t>(c0.y()); iy <= static_cast<int64_t>(c1.y()); ++iy) {
          for (int64_t iz = static_cast<int64_t>(c0.z()); iz <= static_cast<int64_t>(c1.z());
               ++iz) {
            entries.emplace_back(CellKey(ix, iy, iz), static_cast<uint32_t>(i));
          }
        }
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  cell_segments_.reserve(entries.size());
  cells_.reserve(entries.size() / 2 + 1);
  for (size_t i = 0; i < entries.size();) {
    size_t j = i;
    const uint32_t begin = static_cast<uint32_t>(cell_segments_.size());
    while (j < entries.size() && entries[j].first == entries[i].first) {
      cell_segments_.push_back(entries[j].second);
      ++j;
    }
    cells_.emplace(entries[i].first,
                   std::make_pair(begin, static_cast<uint32_t>(cell_segments_.size())));
    i = j;
  }
}

uint64_t EdgeProximityIndex::CellKey(int64_t ix, int64_t iy, int64_t iz) const {
  return (static_cast<uint64_t>((ix + kAxisOffset) & kAxisMask) << 42) |
         (static_cast<uint64_t>((iy + kAxisOffset) & kAxisMask) << 21) |
         static_cast<uint64_t>((iz + kAxisOffset) & kAxisMask);
}

uint64_t EdgeProximityIndex::CellKey(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d c = ((p - origin_) / cell_size_).array().floor();
  return CellKey(static_cast<int64_t>(c.x()), static_cast<int64_t>(c.y()),
                 static_cast<int64_t>(c.z()));
}

double EdgeProximityIndex::NearDistance(const Eigen::Vector3d& p) const {
  const double far = 2.0 * radius_ + 1.0;
  if (segments_.empty() || !p.allFinite()) return far;
  const auto it = cells_.find(CellKey(p));
  if (it == cells_.end()) return far;
  double best = far;
  for (uint32_t k = it->second.first; k < it->second.second; ++k) {
    const EdgeSegment& s = segments_[cell_segments_[k]];
    best = std::min(best, PointSegmentDistance(p, s.a, s.b));
  }
  return best;
}

bool EdgeProximityIndex::Within(const Eigen::Vector3d& p) const {
  return NearDistance(p) <= radius_;
}

}  // namespace edgefit
