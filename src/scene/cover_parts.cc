// Cover shells over one side of a link (accessory_parts.h).
//
// A cover is a sheet bent over the link as seen from one side d of the
// link's box: on a grid over a patch of that side, the sheet's underside
// follows H(cell) + offset, where H is the outermost link surface along d in
// the cell, max-filtered over the 3x3 neighbourhood and then box-averaged.
// The average of the max-filter is still >= the raw height of the centre
// cell (every neighbour's max includes it), so the sheet stays outside the
// sampled surface while losing the stair steps. Cells the link does not
// reach take the lowest height of the patch, so the sheet hangs down there,
// but never more than kMaxDepth below the highest cell.
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "accessory_parts.h"

namespace edgefit {
namespace scene_internal {
namespace {

constexpr double kCell = 0.02;  // [m] grid cell edge, about two sample spacings
constexpr int kMaxCells = 60;   // per side of the patch
constexpr double kMaxDepth = 0.25;  // [m] deepest a sheet bends below its highest cell

// Side d and in-plane axes (e1, e2) with e1 x e2 = d, all link-frame axes.
void SideFrame(int side, Eigen::Vector3d* d, Eigen::Vector3d* e1, Eigen::Vector3d* e2) {
  const int axis = side / 2;
  const double sign = side % 2 == 0 ? 1.0 : -1.0;
  *d = sign * Eigen::Vector3d::Unit(axis);
  *e1 = Eigen::Vector3d::Unit((axis + 1) % 3);
  *e2 = sign * Eigen::Vector3d::Unit((axis + 2) % 3);
}

}  // namespace

bool BuildCover(const PartContext& context, int link, SplitMix64* rng, TriangleMesh* mesh) {
  const AccessoryOptions& options = *context.options;
  const SurfaceCloud& cloud = context.clearance->LinkCloud(link);
  if (cloud.p_world.size() < 50) return false;
  const Pose& T_world_link = (*context.T_world_link)[link];
  const Pose T_link_world = T_world_link.inverse();
  std::vector<Eigen::Vector3d> p_link;
  for (const Eigen::Vector3d& p : cloud.p_world) p_link.push_back(T_link_world * p);

  for (int attempt = 0; attempt < 30; ++attempt) {
    Eigen::Vector3d d, e1, e2;
    SideFrame(rng->Int(0, 5), &d, &e1, &e2);
    const double offset = rng->Uniform(options.cover_offset_min, options.cover_offset_max);
    const double thickness = rng->Uniform(options.cover_thickness_min, options.cover_thickness_max);
    // Later attempts try smaller patches, which fit between neighbours.
    const double f_lo = attempt < 15 ? 0.5 : 0.3, f_hi = attempt < 15 ? 0.85 : 0.5;
    const double f1 = rng->Uniform(f_lo, f_hi), f2 = rng->Uniform(f_lo, f_hi);
    const double c1 = rng->Uniform(), c2 = rng->Uniform();
    // Never under a link that faces the floor from above: real covers are
    // not hung beneath the base.
    if ((T_world_link.linear() * d).z() < -0.7) continue;

    double lo1 = 1e9, hi1 = -1e9, lo2 = 1e9, hi2 = -1e9;
    for (const Eigen::Vector3d& p : p_link) {
      lo1 = std::min(lo1, p.dot(e1)), hi1 = std::max(hi1, p.dot(e1));
      lo2 = std::min(lo2, p.dot(e2)), hi2 = std::max(hi2, p.dot(e2));
    }
    const double size1 = std::min(options.cover_max_side, f1 * (hi1 - lo1));
    const double size2 = std::min(options.cover_max_side, f2 * (hi2 - lo2));
    if (size1 < 0.1 || size2 < 0.1) {
      VLOG(2) << "cover on link " << link << ": patch too small";
      continue;  // too small to be a cover
    }
    const double x0 = lo1 + c1 * (hi1 - lo1 - size1), y0 = lo2 + c2 * (hi2 - lo2 - size2);
    const int nu = std::clamp(static_cast<int>(std::ceil(size1 / kCell)), 2, kMaxCells);
    const int nv = std::clamp(static_cast<int>(std::ceil(size2 / kCell)), 2, kMaxCells);
    const double dx = size1 / nu, dy = size2 / nv;
    auto cell_of = [&](const Eigen::Vector3d& p, int* i, int* j) {
      *i = static_cast<int>(std::floor((p.dot(e1) - x0) / dx));
      *j = static_cast<int>(std::floor((p.dot(e2) - y0) / dy));
      return *i >= 0 && *i < nu && *j >= 0 && *j < nv;
    };

    // Raw outermost height per cell.
    const double kEmpty = -std::numeric_limits<double>::infinity();
    std::vector<double> raw(nu * nv, kEmpty);
    for (const Eigen::Vector3d& p : p_link) {
      int i, j;
      if (cell_of(p, &i, &j)) raw[i + j * nu] = std::max(raw[i + j * nu], p.dot(d));
    }
    double lowest = std::numeric_limits<double>::infinity();
    for (double h : raw) if (h > kEmpty) lowest = std::min(lowest, h);
    if (!std::isfinite(lowest)) continue;
    for (double& h : raw) if (h == kEmpty) h = lowest;
    // A sheet bends over the link, it does not dive into deep recesses or
    // run down a long rail seen end-on: no cell lies more than kMaxDepth
    // below the highest (raising a cell keeps it outside the surface).
    const double highest = *std::max_element(raw.begin(), raw.end());
    for (double& h : raw) h = std::max(h, highest - kMaxDepth);
    // Max-filter then box-average over 3x3 (clamped at the border).
    auto filter = [&](const std::vector<double>& in, bool take_max) {
      std::vector<double> out(in.size());
      for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
          double acc = take_max ? -1e9 : 0.0;
          int count = 0;
          for (int b = std::max(0, j - 1); b <= std::min(nv - 1, j + 1); ++b) {
            for (int a = std::max(0, i - 1); a <= std::min(nu - 1, i + 1); ++a) {
              acc = take_max ? std::max(acc, in[a + b * nu]) : acc + in[a + b * nu];
              ++count;
            }
          }
          out[i + j * nu] = take_max ? acc : acc / count;
        }
      }
      return out;
    };
    const std::vector<double> height = filter(filter(raw, true), false);

    // Another link's surface crossing the sheet (within 10 mm below it to
    // 30 mm above it) would be cut: try elsewhere. A neighbour tucked in
    // the gap under the sheet or clear above it is left alone.
    bool blocked = false;
    for (size_t k = 0; k < context.model->links().size() && !blocked; ++k) {
      if (static_cast<int>(k) == link) continue;
      const SurfaceCloud& other = context.clearance->LinkCloud(static_cast<int>(k));
      for (const Eigen::Vector3d& p_world : other.p_world) {
        const Eigen::Vector3d p = T_link_world * p_world;
        int i, j;
        if (!cell_of(p, &i, &j)) continue;
        const double h = p.dot(d);
        if (h >= height[i + j * nu] + offset - 0.01 &&
            h <= height[i + j * nu] + offset + thickness + 0.03) {
          blocked = true;
          break;
        }
      }
    }
    if (blocked) {
      VLOG(2) << "cover on link " << link << ": patch blocked by another link";
      continue;
    }

    // Corner heights: the highest adjacent cell, plus the offset.
    std::vector<double> bottom((nu + 1) * (nv + 1));
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        double h = -1e9;
        for (int b = std::max(0, j - 1); b <= std::min(nv - 1, j); ++b) {
          for (int a = std::max(0, i - 1); a <= std::min(nu - 1, i); ++a) {
            h = std::max(h, height[a + b * nu]);
          }
        }
        bottom[i + j * (nu + 1)] = h + offset;
      }
    }
    Pose T_link_grid = Pose::Identity();
    T_link_grid.linear().col(0) = e1;
    T_link_grid.linear().col(1) = e2;
    T_link_grid.linear().col(2) = d;
    *mesh = MakeHeightFieldSlab(T_world_link * T_link_grid, x0, y0, dx, dy, nu, nv, bottom,
                                thickness);
    return true;
  }
  return false;
}

}  // namespace scene_internal
}  // namespace edgefit
