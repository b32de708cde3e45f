// The centre axis of a conveyance system (paper Sec. 6.1, Fig. 11b): the
// vertical mirror plane, seen from above as a line, that maps the most arm
// tips onto other tips. RANSAC over pairs of tips: a pair of about equal
// height proposes the perpendicular bisector of the two as the axis, and
// scores it by the tips whose mirror image lands on another tip; tips
// without a symmetric partner are dropped. Every admissible pair (equal
// heights within the tolerance) is tried; beyond `iterations` of them a
// seeded draw of that many.
// The best axis is refined by least squares over its pairs.
#ifndef EDGEFIT_SOLVERS_BASE_SYMMETRY_AXIS_H_
#define EDGEFIT_SOLVERS_BASE_SYMMETRY_AXIS_H_

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace edgefit {

struct SymmetryAxisOptions {
  // A tip's mirror image must lie within `tolerance` of its partner
  // horizontally, and the two heights within `tolerance` of each other [m].
  double tolerance = 0.015;
  double min_pair_width = 0.1;  // [m] between the two tips of a pair
  int iterations = 5000;        // pair hypotheses at most (drawn beyond)
  uint64_t seed = 1;
  // Up to this many distinct axes (apart by more than distinct_angle [rad]
  // or distinct_offset [m]), best first: parallel arms whose pairs are
  // shifted sideways (clamps opened unequally) propose parallel axes.
  int max_axes = 3;
  double distinct_angle = 2.0 * M_PI / 180.0;
  double distinct_offset = 0.02;

  bool IsValid(std::string* error) const;
};

struct SymmetryAxis {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       // on the axis (x, y)
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit
  std::vector<std::pair<int, int>> pairs;                // mirrored tips (indices)
  double rms = 0.0;                                      // [m] of the mirror residuals of the pairs

  Eigen::Vector2d Mirror(const Eigen::Vector2d& p) const;
};

// tips: (x, y, z), z up. Axes with at least one pair, best first (most
// paired tips, then the lower residual).
std::vector<SymmetryAxis> FindSymmetryAxes(const std::vector<Eigen::Vector3d>& tips,
                                           const SymmetryAxisOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_SYMMETRY_AXIS_H_
