// Height map and its convex tips (paper Sec. 6.1, Fig. 11a-b): points are
// projected onto a horizontal grid and each cell keeps its highest point.
// A cell is a convex tip (the apex of an upward arm) when
//   Eq. (13): its second differences in the four directions (Eq. 12, along
//             i, j and both diagonals) all exceed the threshold T:
//             2 P(i,j) - P(i+1,j) - P(i-1,j) > T, and so on; and
//   it is "significantly higher than the surrounding pixels": above every
//             cell two cells away by at least min_drop. Eq. (13) alone also
//             holds at the corner cell of any box top (the outer neighbours
//             are lower, the inner ones level); the ring test rejects those
//             (the inner ring-2 cells are level) and still passes an apex
//             that lies at a cell's border (its adjacent cells may hold a
//             point nearly as high, the ring-2 ones cannot).
// Cells without a point count as lower than any (nothing there), but a tip
// needs at least min_neighbours of its 8 adjacent cells to hold points, so a
// lone stray point is no tip. Tips closer than `separation` to a higher tip
// are dropped (one per arm).
#ifndef EDGEFIT_SOLVERS_BASE_HEIGHT_MAP_H_
#define EDGEFIT_SOLVERS_BASE_HEIGHT_MAP_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

struct ConvexTipOptions {
  double threshold = 0.005;  // Eq. (13) T [m], for the default 1 cm cell
  double min_drop = 0.005;   // [m] above every cell two cells away
  int min_neighbours = 6;    // of the 8 adjacent cells holding a point
  double separation = 0.05;  // [m] between tips (the lower one is dropped)

  bool IsValid(std::string* error) const;
};

// A cell's height must be corroborated: the cell's points within `depth`
// below it (that one included) must be at least `points` and stand for at
// least `cell_share` of the cell's area (each point for the surface its
// beam spacing covers facing its scanner: a count that scales with the
// scan's density). On the realistic conveyor scenes `random_1` and
// `random_18` of the bench (1.7 mm), 3 points alone left 100 and 106
// mixed-pixel tips and a wrong base on `random_18`; 8 points left 2 and
// 2, the arm tips exact. At 6 mm a cell holds a few points per station:
// 5 points lost the clamps' tips of `random_1`, and 3 those of an ideal
// scene of the command-line tests. A quarter of the cell is 9 points at
// 1.7 mm, 2 at 4 and 6 mm.
struct CellSupport {
  int points = 2;
  double cell_share = 0.25;
  double depth = 0.005;  // [m] five range-noise sigmas of 1 mm

  bool IsValid(std::string* error) const;
};

class HeightMap {
 public:
  // A grid of `cell` [m] over the horizontal box `extent` (x, y; z up).
  // Fails when the grid would exceed max_cells (a scan spanning a whole hall
  // at 1 cm: limit it to a region first).
  static Status Create(const Eigen::AlignedBox2d& extent, double cell, HeightMap* map,
                       size_t max_cells = size_t{1} << 24);

  // Keeps p in its cell when it is the cell's highest so far; `source` is
  // the caller's tag of the point (an index). Points outside are ignored.
  void Add(const Eigen::Vector3d& p, int source);

  // Each cell keeps its highest point of `points` that `support`
  // corroborates (source: its index); cells without one stay empty, as do
  // cells already holding a point. areas: per point, the surface it stands
  // for [m^2] (empty: the count alone decides). Deterministic.
  void AddCorroborated(const std::vector<Eigen::Vector3d>& points, const std::vector<float>& areas,
                       const CellSupport& support);

  // Eq. (11)-(13) and the ring test above: one tip per arm, highest first.
  struct Tip {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();  // the cell's highest point
    int source = -1;
  };
  std::vector<Tip> ConvexTips(const ConvexTipOptions& options) const;

  int width() const { return width_; }
  int height() const { return height_; }
  double cell() const { return cell_; }

 private:
  int Index(int i, int j) const { return j * width_ + i; }
  int CellOf(const Eigen::Vector3d& p) const;  // -1 outside (and NaN)
  bool Has(int i, int j) const {
    return i >= 0 && j >= 0 && i < width_ && j < height_ && source_[Index(i, j)] >= 0;
  }

  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double cell_ = 0.01;
  int width_ = 0, height_ = 0;
  std::vector<Eigen::Vector3f> top_;  // highest point per cell, relative to origin_ (x, y)
  std::vector<int> source_;           // -1: no point
};

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_HEIGHT_MAP_H_
