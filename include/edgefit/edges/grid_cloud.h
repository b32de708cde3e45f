// GridCloud: one organized scan as structure-of-arrays floats for the
// lattice-window kernels of paper Sec. 4.1-4.2 (grid_normals.h, edge_score.h).
//
// Cells keep OrganizedScan's column-major order (cell = col * rows + row), so
// the rows of one column of a pixel window are contiguous and the inner loops
// vectorise. Coordinates are in the scanner frame [m]; a missing cell has NaN
// x, y, z and range, so every distance test on it is false.
#ifndef EDGEFIT_EDGES_GRID_CLOUD_H_
#define EDGEFIT_EDGES_GRID_CLOUD_H_

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "edgefit/scan/lattice_window.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct GridCloud {
  int rows = 0;
  int cols = 0;
  // Column cols-1 neighbours column 0 (a full 360 degree scan).
  bool wrap_cols = false;
  float row_step = 0.0f;       // |elevation step| [rad]
  float col_step = 0.0f;       // |azimuth step| [rad]
  std::vector<float> x, y, z;  // p_scanner [m], NaN when missing
  std::vector<float> range;    // |p_scanner| [m], NaN when missing

  size_t size() const { return x.size(); }
  bool IsValid(size_t i) const { return !std::isnan(x[i]); }

  // Copies the points of an organized scan whose lattice is set (CHECKed).
  static GridCloud FromScan(const OrganizedScan& scan);
};

// Calls f(cell_begin, cell_end) for each column segment of the pixel window
// of half size (half_rows, half_cols) around (row, col): the cells of one
// column, rows clipped to the grid, columns wrapped when the scan closes the
// circle and clipped otherwise. Cells [cell_begin, cell_end) are contiguous.
template <typename F>
inline void ForEachWindowColumn(const GridCloud& cloud, int row, int col, int half_rows,
                                int half_cols, F&& f) {
  const int r0 = std::max(0, row - half_rows);
  const int r1 = std::min(cloud.rows - 1, row + half_rows);
  int c0 = col - half_cols, c1 = col + half_cols;
  if (!cloud.wrap_cols || 2 * half_cols + 1 >= cloud.cols) {
    c0 = std::max(0, c0);
    c1 = std::min(cloud.cols - 1, c1);
  }
  for (int c = c0; c <= c1; ++c) {
    int cw = c;
    if (cw < 0) cw += cloud.cols;
    if (cw >= cloud.cols) cw -= cloud.cols;
    const size_t base = static_cast<size_t>(cw) * static_cast<size_t>(cloud.rows);
    f(base + static_cast<size_t>(r0), base + static_cast<size_t>(r1) + 1);
  }
}

}  // namespace edgefit

#endif  // EDGEFIT_EDGES_GRID_CLOUD_H_
