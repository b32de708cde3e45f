// The lattice window that covers a physical radius: the paper's Sec. 4.1
// adaptive pixel window, shared by the edge stage's kernels
// (edges/grid_normals, edges/edge_score) and the floor's lattice differences
// (solvers/base/floor_height).
#ifndef EDGEFIT_SCAN_LATTICE_WINDOW_H_
#define EDGEFIT_SCAN_LATTICE_WINDOW_H_

#include <algorithm>
#include <cmath>

namespace edgefit {

// Half width in pixels of the lattice window that covers `radius` [m] around
// a point at `range` [m] for an angular step `step` [rad] (the pixel radius
// scales inversely with the distance), at least 1 and at most `cap`.
inline int HalfWindow(float radius, float range, float step, int cap) {
  const float pixels = std::ceil(radius / (range * step));
  if (!(pixels < static_cast<float>(cap))) return cap;  // also NaN / inf
  return std::max(1, static_cast<int>(pixels));
}

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_LATTICE_WINDOW_H_
