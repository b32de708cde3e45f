#include "solvers/base/height_map.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>

namespace edgefit {

bool ConvexTipOptions::IsValid(std::string* error) const {
  if (!(threshold >= 0.0) || !(min_drop >= 0.0) || !(separation >= 0.0) || min_neighbours < 0 ||
      min_neighbours > 8) {
    if (error != nullptr) {
      *error =
          "convex tips: threshold, min_drop and separation must be >= 0, "
          "min_neighbours in [0, 8]";
    }
    return false;
  }
  return true;
}

bool CellSupport::IsValid(std::string* error) const {
  if (points < 1 || !(depth >= 0.0) || !(cell_share >= 0.0)) {
    if (error != nullptr) *error = "cell support: points must be >= 1, depth and cell_share >= 0";
    return false;
  }
  return true;
}

Status HeightMap::Create(const Eigen::AlignedBox2d& extent, double cell, HeightMap* map,
                         size_t max_cells) {
  if (!(cell > 0.0)) return Status::Error("height map: the cell size must be > 0");
  if (extent.isEmpty()) return Status::Error("height map: no points");
  const Eigen::Vector2d size = extent.sizes();
  const double cells = std::ceil(size.x() / cell + 1.0) * std::ceil(size.y() / cell + 1.0);
  if (cells > static_cast<double>(max_cells)) {
    char line[200];
    std::snprintf(line, sizeof(line),
                  "height map: the points span %.1f x %.1f m, too large for %.0f mm cells; "
                  "limit the scan to a region around the equipment",
                  size.x(), size.y(), 1e3 * cell);
    return Status::Error(line);
  }
  *map = HeightMap();
  map->origin_ = extent.min();
  map->cell_ = cell;
  map->width_ = static_cast<int>(std::ceil(size.x() / cell + 1.0));
  map->height_ = static_cast<int>(std::ceil(size.y() / cell + 1.0));
  const size_t n = static_cast<size_t>(map->width_) * static_cast<size_t>(map->height_);
  map->top_.assign(n, Eigen::Vector3f::Constant(-std::numeric_limits<float>::infinity()));
  map->source_.assign(n, -1);
  return Status::Ok();
}

int HeightMap::CellOf(const Eigen::Vector3d& p) const {
  const Eigen::Vector2d local = p.head<2>() - origin_;
  const double fi = std::floor(local.x() / cell_), fj = std::floor(local.y() / cell_);
  if (!(fi >= 0.0 && fj >= 0.0 && fi < width_ && fj < height_)) return -1;  // NaN too
  return Index(static_cast<int>(fi), static_cast<int>(fj));
}

void HeightMap::Add(const Eigen::Vector3d& p, int source) {
  const int k = CellOf(p);
  if (k < 0 || (source_[k] >= 0 && !(p.z() > top_[k].z()))) return;
  const Eigen::Vector2d local = p.head<2>() - origin_;
  top_[k] = Eigen::Vector3f(static_cast<float>(local.x()), static_cast<float>(local.y()),
                            static_cast<float>(p.z()));
  source_[k] = source;
}

void HeightMap::AddCorroborated(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<float>& areas, const CellSupport& support) {
  // The points by cell (a counting sort), then each cell's from the top.
  std::vector<int> cell_of(points.size());
  std::vector<int> first(source_.size() + 1, 0);
  for (size_t i = 0; i < points.size(); ++i) {
    cell_of[i] = std::isfinite(points[i].z()) ? CellOf(points[i]) : -1;
    if (cell_of[i] >= 0) ++first[static_cast<size_t>(cell_of[i]) + 1];
  }
  for (size_t k = 0; k < source_.size(); ++k) first[k + 1] += first[k];
  std::vector<int> order(static_cast<size_t>(first.back()));
  std::vector<int> next(first.begin(), first.end() - 1);
  for (size_t i = 0; i < points.size(); ++i) {
    if (cell_of[i] >= 0)
      order[static_cast<size_t>(next[static_cast<size_t>(cell_of[i])]++)] = static_cast<int>(i);
  }
  const std::ptrdiff_t need = support.points;
  const double need_area = support.cell_share * cell_ * cell_;
  auto z_of = [&](int i) { return points[static_cast<size_t>(i)].z(); };
  for (size_t k = 0; k < source_.size(); ++k) {
    if (source_[k] >= 0) continue;
    const auto begin = order.begin() + first[k], end = order.begin() + first[k + 1];
    if (end - begin < need) continue;
    std::sort(begin, end,
              [&](int a, int b) { return z_of(a) != z_of(b) ? z_of(a) > z_of(b) : a < b; });
    for (auto top = begin; end - top >= need; ++top) {
      std::ptrdiff_t count = 0;
      double area = 0.0;
      for (auto below = top; below != end && z_of(*top) - z_of(*below) <= support.depth; ++below) {
        ++count;
        if (!areas.empty()) area += areas[static_cast<size_t>(*below)];
      }
      if (count >= need && (areas.empty() || area >= need_area)) {
        Add(points[static_cast<size_t>(*top)], *top);
        break;
      }
    }
  }
}

std::vector<HeightMap::Tip> HeightMap::ConvexTips(const ConvexTipOptions& options) const {
  const float lowest = -std::numeric_limits<float>::infinity();
  auto P = [&](int i, int j) { return Has(i, j) ? top_[Index(i, j)].z() : lowest; };
  const float T = static_cast<float>(options.threshold);
  const float drop = static_cast<float>(options.min_drop);
  struct Candidate {
    float z;
    int k;
  };
  std::vector<Candidate> candidates;
  for (int j = 0; j < height_; ++j) {
    for (int i = 0; i < width_; ++i) {
      if (!Has(i, j)) continue;
      const float p = P(i, j);
      int neighbours = 0;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) neighbours += (di != 0 || dj != 0) && Has(i + di, j + dj);
      }
      if (neighbours < options.min_neighbours) continue;
      // Eq. (13): the four second differences (a missing cell is -inf: passes).
      const bool convex = 2 * p - P(i + 1, j) - P(i - 1, j) > T &&
                          2 * p - P(i, j + 1) - P(i, j - 1) > T &&
                          2 * p - P(i + 1, j + 1) - P(i - 1, j - 1) > T &&
                          2 * p - P(i + 1, j - 1) - P(i - 1, j + 1) > T;
      if (!convex) continue;
      bool highest = true;  // the ring two cells away
      for (int d = -2; d <= 2 && highest; ++d) {
        highest = P(i + d, j - 2) < p - drop && P(i + d, j + 2) < p - drop &&
                  P(i - 2, j + d) < p - drop && P(i + 2, j + d) < p - drop;
      }
      if (highest) candidates.push_back({p, Index(i, j)});
    }
  }
  // Highest first (ties by cell: deterministic), then one per `separation`.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.z != b.z ? a.z > b.z : a.k < b.k;
  });
  std::vector<Tip> tips;
  const double separation2 = options.separation * options.separation;
  for (const Candidate& c : candidates) {
    Tip tip;
    tip.p = top_[c.k].cast<double>();
    tip.p.head<2>() += origin_;
    tip.source = source_[c.k];
    bool far = true;
    for (const Tip& kept : tips) {
      if ((kept.p.head<2>() - tip.p.head<2>()).squaredNorm() < separation2) {
        far = false;
        break;
      }
    }
    if (far) tips.push_back(tip);
  }
  return tips;
}

}  // namespace edgefit
