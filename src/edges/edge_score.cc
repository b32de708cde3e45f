#include "edgefit/edges/edge_score.h"

#include <glog/logging.h>

#include <cmath>
#include <limits>

namespace edgefit {
namespace {

// S_i of Eq. (4) for a cell with a valid normal; NaN when N_i is empty.
float CellScore(const GridCloud& cloud, const GridNormals& normals, const EdgeScoreOptions& options,
                float r_min2, float r_max2, size_t i) {
  const int row = static_cast<int>(i % static_cast<size_t>(cloud.rows));
  const int col = static_cast<int>(i / static_cast<size_t>(cloud.rows));
  const float r_max = static_cast<float>(options.r_max);
  const int half_rows = HalfWindow(r_max, cloud.range[i], cloud.row_step, options.max_half_window);
  const int half_cols = HalfWindow(r_max, cloud.range[i], cloud.col_step, options.max_half_window);
  const float xi = cloud.x[i], yi = cloud.y[i], zi = cloud.z[i];
  const float nxi = normals.x[i], nyi = normals.y[i], nzi = normals.z[i];
  const float* px = cloud.x.data();
  const float* py = cloud.y.data();
  const float* pz = cloud.z.data();
  const float* nx = normals.x.data();
  const float* ny = normals.y.data();
  const float* nz = normals.z.data();
  float sum = 0.0f;
  int count = 0;
  ForEachWindowColumn(cloud, row, col, half_rows, half_cols, [&](size_t begin, size_t end) {
    float seg_sum = 0.0f;
    int seg_count = 0;
#pragma omp simd reduction(+ : seg_sum, seg_count)
    for (size_t k = begin; k < end; ++k) {
      const float dx = px[k] - xi, dy = py[k] - yi, dz = pz[k] - zi;
      const float d2 = dx * dx + dy * dy + dz * dz;
      const float dot = std::abs(nxi * nx[k] + nyi * ny[k] + nzi * nz[k]);
      // Eq. (3); comparisons with NaN (missing point or normal) are false.
      const bool in = d2 > r_min2 && d2 < r_max2 && dot <= 2.0f;
      seg_sum += in ? dot : 0.0f;
      seg_count += in ? 1 : 0;
    }
    sum += seg_sum;
    count += seg_count;
  });
  return count > 0 ? sum / static_cast<float>(count) : std::numeric_limits<float>::quiet_NaN();
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
  float* out = scores->data();
#pragma omp parallel for schedule(dynamic, 8)
  for (int col = 0; col < cloud.cols; ++col) {
    for (int row = 0; row < rows; ++row) {
      const size_t i = static_cast<size_t>(col) * static_cast<size_t>(rows) + static_cast<size_t>(row);
      // Missing cells and cells without a normal keep NaN.
      if (!cloud.IsValid(i) || !normals.IsValid(i)) continue;
      out[i] = CellScore(cloud, normals, options, r_min2, r_max2, i);
    }
  }
}

}  // namespace edgefit
