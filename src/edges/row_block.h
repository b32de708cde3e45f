// Row blocks of the lattice-window kernels (paper Sec. 4.1-4.2): kLanes
// consecutive rows of one column are processed together, so each neighbour
// offset (dc, dr) of the pixel window is one contiguous vector load shared by
// kLanes output cells, with per-lane window masks reproducing exactly each
// cell's own window (ForEachWindowColumn in grid_cloud.h). Portable GCC
// vector extensions (SSE2 baseline, no -march). Internal to src/edges.
#ifndef EDGEFIT_SRC_EDGES_ROW_BLOCK_H_
#define EDGEFIT_SRC_EDGES_ROW_BLOCK_H_

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "edgefit/edges/grid_cloud.h"

namespace edgefit {
namespace internal {

constexpr int kLanes = 4;
typedef float VecF __attribute__((vector_size(kLanes * sizeof(float))));
typedef int32_t VecI __attribute__((vector_size(kLanes * sizeof(int32_t))));

// Lanes row0 .. row0 + kLanes - 1 of one column (`column` = its first cell);
// rows outside [0, rows) read NaN, which fails every distance test.
inline VecF LoadRows(const float* column, int rows, int row0) {
  VecF v;
  if (row0 >= 0 && row0 + kLanes <= rows) {
    std::memcpy(&v, column + row0, sizeof(v));
    return v;
  }
  for (int j = 0; j < kLanes; ++j) {
    const int r = row0 + j;
    v[j] = r >= 0 && r < rows ? column[r] : std::numeric_limits<float>::quiet_NaN();
  }
  return v;
}

inline VecF Abs(VecF v) { return v < 0.0f ? -v : v; }

// Half windows of the lanes of one block; inactive lanes have -1.
struct RowBlock {
  int col = 0;
  int row0 = 0;
  VecI half_rows{};
  VecI half_cols{};
  VecI wraps{};  // lane's window wraps around (ForEachWindowColumn), else clips
  int max_half_rows = -1;
  int max_half_cols = -1;

  void SetLane(const GridCloud& cloud, int j, int hr, int hc) {
    half_rows[j] = hr;
    half_cols[j] = hc;
    wraps[j] = cloud.wrap_cols && 2 * hc + 1 < cloud.cols ? -1 : 0;
    max_half_rows = std::max(max_half_rows, hr);
    max_half_cols = std::max(max_half_cols, hc);
  }
  bool Empty() const { return max_half_rows < 0; }
};

// A block with all lanes inactive at (col, row0).
inline RowBlock MakeBlock(int col, int row0) {
  RowBlock b;
  b.col = col;
  b.row0 = row0;
  for (int j = 0; j < kLanes; ++j) b.half_rows[j] = b.half_cols[j] = -1;
  return b;
}

// Calls f(base, row0 + dr, mask) for each offset of the union of the lanes'
// windows; `base` is the first cell of the neighbour column and mask lane j
// is true (-1) when the offset lies in lane j's window.
template <typename F>
inline void ForEachBlockOffset(const GridCloud& cloud, const RowBlock& b, F&& f) {
  for (int dc = -b.max_half_cols; dc <= b.max_half_cols; ++dc) {
    int c = b.col + dc;
    const int adc = dc < 0 ? -dc : dc;
    VecI col_mask = b.half_cols >= adc;
    if (c < 0 || c >= cloud.cols) {
      if (!cloud.wrap_cols) continue;
      c = ((c % cloud.cols) + cloud.cols) % cloud.cols;
      col_mask &= b.wraps;
    }
    const size_t base = static_cast<size_t>(c) * static_cast<size_t>(cloud.rows);
    for (int dr = -b.max_half_rows; dr <= b.max_half_rows; ++dr) {
      const int adr = dr < 0 ? -dr : dr;
      const VecI mask = col_mask & (b.half_rows >= adr);
      f(base, b.row0 + dr, mask);
    }
  }
}

}  // namespace internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_EDGES_ROW_BLOCK_H_
