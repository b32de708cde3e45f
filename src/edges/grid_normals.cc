#include "edgefit/edges/grid_normals.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "row_block.h"
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

using internal::kLanes;
using internal::VecF;
using internal::VecI;

// WPCA normals (Sec. 4.1) of the kLanes cells of one row block: with
// `initial` == nullptr stage 1 over all neighbours within the radius,
// otherwise stage 2 over those whose initial normals satisfy Eq. (2). Both
// stages weight by Eq. (1) with h from the whole (unfiltered) neighbourhood.
// A lane gets false in ok[] with fewer than kMinNeighbours neighbours.
// `scales` (optional) holds per cell the Eq. (1) exponent scale -2 / d_max^2
// (NaN: too few neighbours): stage 1 writes it, stage 2 reads it instead of
// recomputing pass A (the unfiltered neighbourhood is the same).
void BlockNormals(const GridCloud& cloud, const GridNormalOptions& options,
                  const internal::RowBlock& block, const GridNormals* initial,
                  std::vector<float>* scales, Eigen::Vector3f n[kLanes], bool ok[kLanes]) {
  const float radius = static_cast<float>(options.radius);
  const float radius2 = radius * radius;
  const int rows = cloud.rows;
  const size_t self = static_cast<size_t>(block.col) * static_cast<size_t>(rows);
  const float* px = cloud.x.data();
  const float* py = cloud.y.data();
  const float* pz = cloud.z.data();
  const VecF xi = internal::LoadRows(px + self, rows, block.row0);
  const VecF yi = internal::LoadRows(py + self, rows, block.row0);
  const VecF zi = internal::LoadRows(pz + self, rows, block.row0);

  // Pass A: neighbour count and the largest neighbour distance (h = d_max / 2).
  const bool cached = scales != nullptr && initial != nullptr;
  VecF d2_max{};
  VecI count{};
  if (!cached) internal::ForEachBlockOffset(cloud, block, [&](size_t base, int r, VecI mask) {
    const VecF dx = internal::LoadRows(px + base, rows, r) - xi;
    const VecF dy = internal::LoadRows(py + base, rows, r) - yi;
    const VecF dz = internal::LoadRows(pz + base, rows, r) - zi;
    const VecF d2 = dx * dx + dy * dy + dz * dz;
    const VecI in = mask & (d2 <= radius2);  // false for NaN (missing cells)
    d2_max = in & (d2 > d2_max) ? d2 : d2_max;
    count -= in;
  });

  // Pass B: Eq. (1) weights w = exp(-2 d^2 / d_max^2), weighted moments of
  // the offsets, Eq. (2) filter in stage 2.
  const VecF nan = VecF{} + std::numeric_limits<float>::quiet_NaN();
  const VecF exponent_scale =
      cached ? internal::LoadRows(scales->data() + self, rows, block.row0)
             : ((count >= kMinNeighbours) & (d2_max > 0.0f) ? -2.0f / d2_max : nan);
  if (scales != nullptr && !cached) {
    for (int j = 0; j < kLanes && block.row0 + j < rows; ++j) {
      (*scales)[self + static_cast<size_t>(block.row0 + j)] = exponent_scale[j];
    }
  }
  const VecF tau_align = VecF{} + static_cast<float>(options.tau_align);
  const float* nx = initial != nullptr ? initial->x.data() : nullptr;
  const float* ny = initial != nullptr ? initial->y.data() : nullptr;
  const float* nz = initial != nullptr ? initial->z.data() : nullptr;
  VecF nxi{}, nyi{}, nzi{};
  if (nx != nullptr) {
    nxi = internal::LoadRows(nx + self, rows, block.row0);
    nyi = internal::LoadRows(ny + self, rows, block.row0);
    nzi = internal::LoadRows(nz + self, rows, block.row0);
  }
  VecF w{}, sx{}, sy{}, sz{}, xx{}, xy{}, xz{}, yy{}, yz{}, zz{};
  VecI kept{};
  internal::ForEachBlockOffset(cloud, block, [&](size_t base, int r, VecI mask) {
    const VecF dx = internal::LoadRows(px + base, rows, r) - xi;
    const VecF dy = internal::LoadRows(py + base, rows, r) - yi;
    const VecF dz = internal::LoadRows(pz + base, rows, r) - zi;
    const VecF d2 = dx * dx + dy * dy + dz * dz;
    VecI in = mask & (d2 <= radius2);
    if (nx != nullptr) {
      const VecF align = internal::Abs(nxi * internal::LoadRows(nx + base, rows, r) +
                                       nyi * internal::LoadRows(ny + base, rows, r) +
                                       nzi * internal::LoadRows(nz + base, rows, r));
      in &= align > tau_align;  // Eq. (2); NaN normals fail
    }
    const VecF wk = in ? internal::GaussianWeightExp(exponent_scale * d2) : VecF{};
    const VecF ex = in ? dx : VecF{};
    const VecF ey = in ? dy : VecF{};
    const VecF ez = in ? dz : VecF{};
    kept -= in;
    w += wk;
    const VecF wx = wk * ex, wy = wk * ey, wz = wk * ez;
    sx += wx; sy += wy; sz += wz;
    xx += wx * ex; xy += wx * ey; xz += wx * ez;
    yy += wy * ey; yz += wy * ez; zz += wz * ez;
  });
  for (int j = 0; j < kLanes; ++j) {
    ok[j] = false;
    if (block.half_rows[j] < 0 || std::isnan(exponent_scale[j]) || kept[j] < kMinNeighbours) {
      continue;
    }
    internal::WeightedMoments m;
    m.w = w[j];
    m.sx = sx[j]; m.sy = sy[j]; m.sz = sz[j];
    m.xx = xx[j]; m.xy = xy[j]; m.xz = xz[j];
    m.yy = yy[j]; m.yz = yz[j]; m.zz = zz[j];
    ok[j] = internal::NormalFromMoments(m, Eigen::Vector3f(xi[j], yi[j], zi[j]), &n[j]);
  }
}

void RunStage(const GridCloud& cloud, const GridNormalOptions& options, const GridNormals* initial,
              std::vector<float>* scales, GridNormals* out) {
  out->Resize(cloud.size());
  const int rows = cloud.rows;
  const float radius = static_cast<float>(options.radius);
  // Columns are independent; dynamic scheduling balances near (large
  // window) and empty columns. Results do not depend on the schedule.
#pragma omp parallel for schedule(dynamic, 8)
  for (int col = 0; col < cloud.cols; ++col) {
    const size_t col_base = static_cast<size_t>(col) * static_cast<size_t>(rows);
    for (int row0 = 0; row0 < rows; row0 += kLanes) {
      internal::RowBlock block = internal::MakeBlock(col, row0);
      for (int j = 0; j < kLanes && row0 + j < rows; ++j) {
        const size_t i = col_base + static_cast<size_t>(row0 + j);
        if (!cloud.IsValid(i)) continue;
        block.SetLane(cloud, j,
                      HalfWindow(radius, cloud.range[i], cloud.row_step, options.max_half_window),
                      HalfWindow(radius, cloud.range[i], cloud.col_step, options.max_half_window));
      }
      if (block.Empty()) continue;  // out->Resize filled NaN
      Eigen::Vector3f n[kLanes];
      bool ok[kLanes];
      BlockNormals(cloud, options, block, initial, scales, n, ok);
      for (int j = 0; j < kLanes && row0 + j < rows; ++j) {
        const size_t i = col_base + static_cast<size_t>(row0 + j);
        if (block.half_rows[j] < 0) {
          SetMissing(i, out);
        } else if (ok[j]) {
          SetNormal(i, n[j], out);
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
  RunStage(cloud, options, nullptr, nullptr, initial);
}

void RefineNormals(const GridCloud& cloud, const GridNormalOptions& options,
                   const GridNormals& initial, GridNormals* normals) {
  CHECK(normals != nullptr && normals != &initial);
  CHECK_EQ(initial.size(), cloud.size());
  RunStage(cloud, options, &initial, nullptr, normals);
}

void EstimateGridNormals(const GridCloud& cloud, const GridNormalOptions& options,
                         GridNormals* normals) {
  CHECK(normals != nullptr);
  GridNormals initial;
  std::vector<float> scales(cloud.size(), kNaN);  // Eq. (1) scales shared by both stages
  RunStage(cloud, options, nullptr, &scales, &initial);
  RunStage(cloud, options, &initial, &scales, normals);
}

}  // namespace edgefit
