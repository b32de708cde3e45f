#include "edgefit/edges/grid_normals.h"

#include <glog/logging.h>

#include <algorithm>
#include <limits>

#include "weighted_pca.h"

namespace edgefit {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// Fewest neighbours (the point itself included) that define a plane.
constexpr int kMinNeighbours = 3;

void SetNormal(size_t i, const Eigen::Vector3f& n, GridNormals* normals) {
  normals->x[i] = n.x();
  normals->y[i] = n.y();
  normals->z[i] = n.z();
}

void SetMissing(size_t i, GridNormals* normals) {
  normals->x[i] = normals->y[i] = normals->z[i] = kNaN;
}

// WPCA normal of cell i (Sec. 4.1). With `initial` == nullptr: stage 1 over
// all neighbours within the radius; otherwise stage 2 over those whose
// initial normals satisfy Eq. (2). Both stages weight by Eq. (1) with h from
// the whole (unfiltered) neighbourhood. Returns false with fewer than
// kMinNeighbours neighbours.
bool CellNormal(const GridCloud& cloud, const GridNormalOptions& options, size_t i,
                const GridNormals* initial, Eigen::Vector3f* n) {
  const float radius = static_cast<float>(options.radius);
  const float radius2 = radius * radius;
  const int row = static_cast<int>(i % static_cast<size_t>(cloud.rows));
  const int col = static_cast<int>(i / static_cast<size_t>(cloud.rows));
  const float xi = cloud.x[i], yi = cloud.y[i], zi = cloud.z[i];
  const int half_rows = HalfWindow(radius, cloud.range[i], cloud.row_step, options.max_half_window);
  const int half_cols = HalfWindow(radius, cloud.range[i], cloud.col_step, options.max_half_window);
  const float* px = cloud.x.data();
  const float* py = cloud.y.data();
  const float* pz = cloud.z.data();

  // Pass A: neighbour count and the largest neighbour distance (h = d_max / 2).
  float d2_max = 0.0f;
  int count = 0;
  ForEachWindowColumn(cloud, row, col, half_rows, half_cols, [&](size_t begin, size_t end) {
    float seg_max = 0.0f;
    int seg_count = 0;
#pragma omp simd reduction(max : seg_max) reduction(+ : seg_count)
    for (size_t k = begin; k < end; ++k) {
      const float dx = px[k] - xi, dy = py[k] - yi, dz = pz[k] - zi;
      const float d2 = dx * dx + dy * dy + dz * dz;
      const bool in = d2 <= radius2;  // false for NaN (missing cells)
      seg_max = in ? std::max(seg_max, d2) : seg_max;
      seg_count += in ? 1 : 0;
    }
    d2_max = std::max(d2_max, seg_max);
    count += seg_count;
  });
  if (count < kMinNeighbours || !(d2_max > 0.0f)) return false;

  // Pass B: Eq. (1) weights w = exp(-d^2 / (2 h^2)) = exp(-2 d^2 / d_max^2),
  // weighted moments of the offsets, Eq. (2) filter in stage 2.
  const float exponent_scale = -2.0f / d2_max;
  const float tau_align = static_cast<float>(options.tau_align);
  const float* nx = initial != nullptr ? initial->x.data() : nullptr;
  const float* ny = initial != nullptr ? initial->y.data() : nullptr;
  const float* nz = initial != nullptr ? initial->z.data() : nullptr;
  const float nxi = nx != nullptr ? nx[i] : 0.0f;
  const float nyi = ny != nullptr ? ny[i] : 0.0f;
  const float nzi = nz != nullptr ? nz[i] : 0.0f;
  internal::WeightedMoments m;
  int kept = 0;
  ForEachWindowColumn(cloud, row, col, half_rows, half_cols, [&](size_t begin, size_t end) {
    float w = 0, sx = 0, sy = 0, sz = 0, xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    int seg_kept = 0;
    if (nx == nullptr) {
#pragma omp simd reduction(+ : w, sx, sy, sz, xx, xy, xz, yy, yz, zz, seg_kept)
      for (size_t k = begin; k < end; ++k) {
        const float dx = px[k] - xi, dy = py[k] - yi, dz = pz[k] - zi;
        const float d2 = dx * dx + dy * dy + dz * dz;
        const float wk = d2 <= radius2 ? internal::GaussianWeightExp(exponent_scale * d2) : 0.0f;
        const float ex = d2 <= radius2 ? dx : 0.0f;
        const float ey = d2 <= radius2 ? dy : 0.0f;
        const float ez = d2 <= radius2 ? dz : 0.0f;
        seg_kept += d2 <= radius2 ? 1 : 0;
        w += wk;
        sx += wk * ex; sy += wk * ey; sz += wk * ez;
        xx += wk * ex * ex; xy += wk * ex * ey; xz += wk * ex * ez;
        yy += wk * ey * ey; yz += wk * ey * ez; zz += wk * ez * ez;
      }
    } else {
#pragma omp simd reduction(+ : w, sx, sy, sz, xx, xy, xz, yy, yz, zz, seg_kept)
      for (size_t k = begin; k < end; ++k) {
        const float dx = px[k] - xi, dy = py[k] - yi, dz = pz[k] - zi;
        const float d2 = dx * dx + dy * dy + dz * dz;
        const float align = std::abs(nxi * nx[k] + nyi * ny[k] + nzi * nz[k]);
        const bool in = d2 <= radius2 && align > tau_align;  // Eq. (2); NaN normals fail
        const float wk = in ? internal::GaussianWeightExp(exponent_scale * d2) : 0.0f;
        const float ex = in ? dx : 0.0f;
        const float ey = in ? dy : 0.0f;
        const float ez = in ? dz : 0.0f;
        seg_kept += in ? 1 : 0;
        w += wk;
        sx += wk * ex; sy += wk * ey; sz += wk * ez;
        xx += wk * ex * ex; xy += wk * ex * ey; xz += wk * ex * ez;
        yy += wk * ey * ey; yz += wk * ey * ez; zz += wk * ez * ez;
      }
    }
    m.w += w;
    m.sx += sx; m.sy += sy; m.sz += sz;
    m.xx += xx; m.xy += xy; m.xz += xz;
    m.yy += yy; m.yz += yz; m.zz += zz;
    kept += seg_kept;
  });
  if (kept < kMinNeighbours) return false;
  return internal::NormalFromMoments(m, Eigen::Vector3f(xi, yi, zi), n);
}

void RunStage(const GridCloud& cloud, const GridNormalOptions& options, const GridNormals* initial,
              GridNormals* out) {
  out->Resize(cloud.size());
  const int rows = cloud.rows;
  // Columns are independent; dynamic scheduling balances near (large
  // window) and empty columns. Results do not depend on the schedule.
#pragma omp parallel for schedule(dynamic, 8)
  for (int col = 0; col < cloud.cols; ++col) {
    for (int row = 0; row < rows; ++row) {
      const size_t i = static_cast<size_t>(col) * static_cast<size_t>(rows) + static_cast<size_t>(row);
      Eigen::Vector3f n;
      if (!cloud.IsValid(i)) {
        SetMissing(i, out);
      } else if (CellNormal(cloud, options, i, initial, &n)) {
        SetNormal(i, n, out);
      } else if (initial != nullptr && initial->IsValid(i)) {
        // Stage 2 kept too few neighbours: keep n^(0).
        out->x[i] = initial->x[i];
        out->y[i] = initial->y[i];
        out->z[i] = initial->z[i];
      } else {
        SetMissing(i, out);
      }
    }
  }
}

}  // namespace

void GridNormals::Resize(size_t n) {
  x.assign(n, kNaN);
  y.assign(n, kNaN);
  z.assign(n, kNaN);
}

void EstimateInitialNormals(const GridCloud& cloud, const GridNormalOptions& options,
                            GridNormals* initial) {
  CHECK(initial != nullptr);
  RunStage(cloud, options, nullptr, initial);
}

void RefineNormals(const GridCloud& cloud, const GridNormalOptions& options,
                   const GridNormals& initial, GridNormals* normals) {
  CHECK(normals != nullptr && normals != &initial);
  CHECK_EQ(initial.size(), cloud.size());
  RunStage(cloud, options, &initial, normals);
}

void EstimateGridNormals(const GridCloud& cloud, const GridNormalOptions& options,
                         GridNormals* normals) {
  GridNormals initial;
  EstimateInitialNormals(cloud, options, &initial);
  RefineNormals(cloud, options, initial, normals);
}

}  // namespace edgefit
