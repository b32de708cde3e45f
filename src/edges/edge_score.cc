#include "edgefit/edges/edge_score.h"

#include <glog/logging.h>

#include <cmath>
#include <limits>

#include "row_block.h"

namespace edgefit {
namespace {

using internal::kLanes;
using internal::VecF;
using internal::VecI;

// S_i of Eq. (4) for the lanes of one row block (cells with a valid normal);
// NaN when N_i is empty.
void BlockScores(const GridCloud& cloud, const GridNormals& normals, float r_min2, float r_max2,
                 const internal::RowBlock& block, float score[kLanes]) {
  const int rows = cloud.rows;
  const size_t self = static_cast<size_t>(block.col) * static_cast<size_t>(rows);
  const float* px = cloud.x.data();
  const float* py = cloud.y.data();
  const float* pz = cloud.z.data();
  const float* nx = normals.x.data();
  const float* ny = normals.y.data();
  const float* nz = normals.z.data();
  const VecF xi = internal::LoadRows(px + self, rows, block.row0);
  const VecF yi = internal::LoadRows(py + self, rows, block.row0);
  const VecF zi = internal::LoadRows(pz + self, rows, block.row0);
  const VecF nxi = internal::LoadRows(nx + self, rows, block.row0);
  const VecF nyi = internal::LoadRows(ny + self, rows, block.row0);
  const VecF nzi = internal::LoadRows(nz + self, rows, block.row0);
  VecF sum{};
  VecI count{};
  internal::ForEachBlockOffset(cloud, block, [&](size_t base, int r, VecI mask) {
    const VecF dx = internal::LoadRows(px + base, rows, r) - xi;
    const VecF dy = internal::LoadRows(py + base, rows, r) - yi;
    const VecF dz = internal::LoadRows(pz + base, rows, r) - zi;
    const VecF d2 = dx * dx + dy * dy + dz * dz;
    const VecF dot = internal::Abs(nxi * internal::LoadRows(nx + base, rows, r) +
                                   nyi * internal::LoadRows(ny + base, rows, r) +
                                   nzi * internal::LoadRows(nz + base, rows, r));
    // Eq. (3); comparisons with NaN (missing point or normal) are false.
    const VecI in = mask & (d2 > r_min2) & (d2 < r_max2) & (dot <= 2.0f);
    sum += in ? dot : VecF{};
    count -= in;
  });
  for (int j = 0; j < kLanes; ++j) {
    score[j] = count[j] > 0 ? sum[j] / static_cast<float>(count[j])
                            : std::numeric_limits<float>::quiet_NaN();
  }
}

}  // namespace

void ComputeEdgeScores(const GridCloud& cloud, const GridNormals& normals,
                       const EdgeScoreOptions& options, std::vector<float>* scores) {
  CHECK(scores != nullptr);
  CHECK_EQ(normals.size(), cloud.size());
  scores->assign(cloud.size(), std::numeric_limits<float>::quiet_NaN());
  const float r_min2 = static_cast<float>(options.r_min * options.r_min);
  const float r_max2 = static_cast<float>(options.r_max * options.r_max);
  const int rows = cloud.rows;
  const float r_max = static_cast<float>(options.r_max);
  float* out = scores->data();
#pragma omp parallel for schedule(dynamic, 8)
  for (int col = 0; col < cloud.cols; ++col) {
    const size_t col_base = static_cast<size_t>(col) * static_cast<size_t>(rows);
    for (int row0 = 0; row0 < rows; row0 += kLanes) {
      internal::RowBlock block = internal::MakeBlock(col, row0);
      for (int j = 0; j < kLanes && row0 + j < rows; ++j) {
        const size_t i = col_base + static_cast<size_t>(row0 + j);
        // Missing cells and cells without a normal keep NaN.
        if (!cloud.IsValid(i) || !normals.IsValid(i)) continue;
        block.SetLane(cloud, j,
                      HalfWindow(r_max, cloud.range[i], cloud.row_step, options.max_half_window),
                      HalfWindow(r_max, cloud.range[i], cloud.col_step, options.max_half_window));
      }
      if (block.Empty()) continue;
      float score[kLanes];
      BlockScores(cloud, normals, r_min2, r_max2, block, score);
      for (int j = 0; j < kLanes && row0 + j < rows; ++j) {
        if (block.half_rows[j] >= 0) out[col_base + static_cast<size_t>(row0 + j)] = score[j];
      }
    }
  }
}

}  // namespace edgefit
