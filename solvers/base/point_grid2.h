// A hash grid over 2D points for radius queries: the cross-section corner
// curvature (cross_sections.cc) and the base RANSAC score (base_rough.cc).
// Internal to edgefit::solvers. Borrows the points; cell size = the usual
// query radius, so a query visits 3 x 3 cells. A bit per cell of the
// points' box says whether any point lies in its 3 x 3 cells: a query of at
// most a cell's radius there answers "none" with one look, without the
// hash (most of the RANSAC's queries land far from every point).
#ifndef EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_
#define EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace edgefit {

class PointGrid2 {
 public:
  PointGrid2(const std::vector<Eigen::Vector2d>& points, double cell)
      : points_(points), cell_(cell) {
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (size_t i = 0; i < points.size(); ++i) {
      const int64_t cx = Coord(points[i].x()), cy = Coord(points[i].y());
      cells_[Pack(cx, cy)].push_back(static_cast<int>(i));
      x0 = std::min(x0, cx);
      y0 = std::min(y0, cy);
      x1 = std::max(x1, cx);
      y1 = std::max(y1, cy);
    }
    if (points.empty()) return;
    // The box grown by a cell each way, when its bits fit kMaxNearBits.
    const double bits = (static_cast<double>(x1 - x0) + 3.0) * (static_cast<double>(y1 - y0) + 3.0);
    if (bits > kMaxNearBits) return;
    near_x0_ = x0 - 1;
    near_y0_ = y0 - 1;
    near_width_ = x1 - x0 + 3;
    near_height_ = y1 - y0 + 3;
    near_.assign(static_cast<size_t>((near_width_ * near_height_ + 63) / 64), 0);
    for (const Eigen::Vector2d& point : points) {
      const int64_t cx = Coord(point.x()) - near_x0_, cy = Coord(point.y()) - near_y0_;
      for (int64_t dx = -1; dx <= 1; ++dx) {
        for (int64_t dy = -1; dy <= 1; ++dy) {
          const size_t bit = static_cast<size_t>((cy + dy) * near_width_ + cx + dx);
          near_[bit / 64] |= uint64_t{1} << (bit % 64);
        }
      }
    }
  }

  // Calls f(j) for every point j within radius of p; f returns true to stop.
  // Returns true when f stopped the search.
  template <typename F>
  bool ForNeighbors(const Eigen::Vector2d& p, double radius, F&& f) const {
    const int64_t cx = Coord(p.x()), cy = Coord(p.y());
    const int64_t reach = static_cast<int64_t>(std::ceil(radius / cell_));
    for (int64_t dx = -reach; dx <= reach; ++dx) {
      for (int64_t dy = -reach; dy <= reach; ++dy) {
        const auto it = cells_.find(Pack(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const int j : it->second) {
          if ((points_[static_cast<size_t>(j)] - p).squaredNorm() <= radius * radius && f(j)) {
            return true;
          }
        }
      }
    }
    return false;
  }

  // Whether some point lies within radius of p.
  bool AnyWithin(const Eigen::Vector2d& p, double radius) const {
    if (radius <= cell_ && !NearAny(Coord(p.x()), Coord(p.y()))) return false;
    return ForNeighbors(p, radius, [](int) { return true; });
  }

 private:
  static constexpr double kMaxNearBits = 1u << 30;  // 128 MiB

  // Whether a point lies in the 3 x 3 cells about cell (cx, cy); true
  // when no bits were kept.
  bool NearAny(int64_t cx, int64_t cy) const {
    if (near_.empty()) return true;
    const int64_t x = cx - near_x0_, y = cy - near_y0_;
    if (x < 0 || y < 0 || x >= near_width_ || y >= near_height_) return false;
    const size_t bit = static_cast<size_t>(y * near_width_ + x);
    return (near_[bit / 64] >> (bit % 64)) & 1u;
  }
  int64_t Coord(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  static int64_t Pack(int64_t x, int64_t y) {  // unsigned shift: no UB for negative x
    return static_cast<int64_t>((static_cast<uint64_t>(x) << 32) ^
                                (static_cast<uint64_t>(y) & 0xffffffffULL));
  }

  const std::vector<Eigen::Vector2d>& points_;
  double cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
  std::vector<uint64_t> near_;  // row-major bits over the box, row y, column x
  int64_t near_x0_ = 0, near_y0_ = 0, near_width_ = 0, near_height_ = 0;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_
