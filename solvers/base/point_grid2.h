// A hash grid over 2D points for radius queries: the cross-section corner
// curvature (cross_sections.cc) and the base RANSAC score (base_rough.cc).
// Internal to edgefit::solvers. Borrows the points; cell size = the usual
// query radius, so a query visits 3 x 3 cells.
#ifndef EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_
#define EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace edgefit {

class PointGrid2 {
 public:
  PointGrid2(const std::vector<Eigen::Vector2d>& points, double cell)
      : points_(points), cell_(cell) {
    for (size_t i = 0; i < points.size(); ++i) {
      cells_[Pack(Coord(points[i].x()), Coord(points[i].y()))].push_back(static_cast<int>(i));
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
    return ForNeighbors(p, radius, [](int) { return true; });
  }

 private:
  int64_t Coord(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }
  static int64_t Pack(int64_t x, int64_t y) {  // unsigned shift: no UB for negative x
    return static_cast<int64_t>((static_cast<uint64_t>(x) << 32) ^
                                (static_cast<uint64_t>(y) & 0xffffffffULL));
  }

  const std::vector<Eigen::Vector2d>& points_;
  double cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_POINT_GRID2_H_
