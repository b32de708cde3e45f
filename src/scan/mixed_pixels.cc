#include "edgefit/scan/mixed_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace edgefit {

bool MixedPixelOptions::IsValid(std::string* error) const {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance) || min_lines < 1 || min_lines > 4 ||
      neighbour_lines < 0 || neighbour_lines > 4 || !(tolerance_per_spacing >= 0.0)) {
    if (error != nullptr) {
      *error =
          "mixed pixels: tolerance must be > 0, tolerance_per_spacing >= 0, min_lines in 1..4, "
          "neighbour_lines in 0..4";
    }
    return false;
  }
  return true;
}

namespace {

// The grid's angular step: a cell's spacing is its range times it (0
// without a lattice).
double LatticeStep(const OrganizedScan& scan) {
  return std::max(std::abs(scan.lattice().row_step()), std::abs(scan.lattice().col_step()));
}

// How far off a surface a cell at range r must lie to be taken as off it.
double Tolerance(const MixedPixelOptions& options, double r, double step) {
  return std::max(options.tolerance, options.tolerance_per_spacing * r * step);
}

}  // namespace

std::vector<uint8_t> FindMixedPixels(const OrganizedScan& scan, const MixedPixelOptions& options) {
  std::vector<uint8_t> mixed(scan.size(), 0);
  if (!scan.organized()) return mixed;
  // Lines along which each cell is mixed.
  std::vector<uint8_t> line_count(scan.size(), 0);
  const int rows = scan.rows(), cols = scan.cols();
  const double step = LatticeStep(scan);
  const float nan = std::numeric_limits<float>::quiet_NaN();

  // Row, column and the two diagonals; each reaches two cells either way.
  constexpr int kLines[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};
  constexpr int kReach = 2, kHeld = 2 * kReach + 1;
#pragma omp parallel
  {
    // The ranges of the columns col - 2 .. col + 2 (NaN: missing or off
    // the grid), each computed once as a thread's columns go by.
    std::array<std::vector<float>, kHeld> held_ranges;
    std::array<int, kHeld> held_col;
    held_col.fill(std::numeric_limits<int>::min());
    auto column = [&](int col) -> const std::vector<float>& {
      const size_t slot = static_cast<size_t>(((col % kHeld) + kHeld) % kHeld);
      std::vector<float>& ranges = held_ranges[slot];
      if (held_col[slot] != col) {
        held_col[slot] = col;
        ranges.assign(static_cast<size_t>(rows), nan);
        if (col >= 0 && col < cols) {
          for (int row = 0; row < rows; ++row) {
            const size_t i = scan.Index(row, col);
            if (scan.IsValid(i)) ranges[static_cast<size_t>(row)] = scan.point_scanner(i).norm();
          }
        }
      }
      return ranges;
    };
#pragma omp for schedule(static)
    for (int col = 0; col < cols; ++col) {
      std::array<const std::vector<float>*, kHeld> near;  // columns col - 2 .. col + 2
      for (int k = 0; k < kHeld; ++k) near[static_cast<size_t>(k)] = &column(col - kReach + k);
      auto range = [&](int row, int dc) -> double {
        if (row < 0 || row >= rows) return std::nan("");
        const std::vector<float>& ranges = *near[static_cast<size_t>(dc + kReach)];
        return static_cast<double>(ranges[static_cast<size_t>(row)]);
      };
      for (int row = 0; row < rows; ++row) {
        const double r = range(row, 0);
        if (std::isnan(r)) continue;
        const double tol = Tolerance(options, r, step);
        int lines = 0;
        for (const auto& line : kLines) {
          const int dr = line[0], dc = line[1];
          const double a1 = range(row - dr, -dc), b1 = range(row + dr, dc);
          if (std::isnan(a1) || std::isnan(b1)) continue;
          if (!(r > std::min(a1, b1) + tol && r < std::max(a1, b1) - tol)) continue;
          const double a2 = range(row - 2 * dr, -2 * dc);
          const double b2 = range(row + 2 * dr, 2 * dc);
          const double from_a = std::isnan(a2) ? a1 : 2.0 * a1 - a2;
          const double from_b = std::isnan(b2) ? b1 : 2.0 * b1 - b2;
          lines += std::abs(r - from_a) > tol && std::abs(r - from_b) > tol;
        }
        line_count[scan.Index(row, col)] = static_cast<uint8_t>(lines);
      }
    }
  }
  // A cell mixed along min_lines, or along neighbour_lines beside one that is.
  auto is_seed = [&](int row, int col) {
    return row >= 0 && row < rows && col >= 0 && col < cols &&
           line_count[scan.Index(row, col)] >= options.min_lines;
  };
#pragma omp parallel for schedule(static)
  for (int col = 0; col < cols; ++col) {
    for (int row = 0; row < rows; ++row) {
      const int lines = line_count[scan.Index(row, col)];
      bool is_mixed = lines >= options.min_lines;
      if (!is_mixed && options.neighbour_lines > 0 && lines >= options.neighbour_lines) {
        for (int dr = -1; dr <= 1 && !is_mixed; ++dr) {
          for (int dc = -1; dc <= 1 && !is_mixed; ++dc) is_mixed = is_seed(row + dr, col + dc);
        }
      }
      mixed[scan.Index(row, col)] = is_mixed;
    }
  }
  return mixed;
}

std::vector<std::vector<uint8_t>> FindMixedPixels(const ScanSet& scans,
                                                  const MixedPixelOptions& options, size_t* count) {
  std::vector<std::vector<uint8_t>> mixed;
  *count = 0;
  for (const OrganizedScan& scan : scans.scans) {
    mixed.push_back(FindMixedPixels(scan, options));
    for (const uint8_t m : mixed.back()) *count += m;
  }
  return mixed;
}

namespace {

// The silhouette mixed pixels of one scan (MarkSilhouetteMixedPixels):
// sets out[i] = 1 for those found where out[i] was 0; returns how many.
size_t MarkSilhouetteMixedPixels(const OrganizedScan& scan, const std::vector<uint8_t>& object,
                                 const MixedPixelOptions& options, int radius, std::vector<uint8_t>* out) {
  if (!scan.organized()) return 0;
  const int rows = scan.rows(), cols = scan.cols();
  const auto inside = [&](int row, int col) { return row >= 0 && row < rows && col >= 0 && col < cols; };
  // Range of a cell not of the object, NaN when missing, of the object or off the grid.
  const auto behind = [&](int row, int col) -> double {
    if (!inside(row, col)) return std::nan("");
    const size_t i = scan.Index(row, col);
    return scan.IsValid(i) && object[i] == 0 ? static_cast<double>(scan.point_scanner(i).norm()) : std::nan("");
  };
  // Whether a cell of the object lies within `radius` cells back along
  // (dr, dc), nearer than r - tol.
  const auto object_before = [&](int row, int col, int dr, int dc, double r, double tol) {
    for (int k = 1; k <= radius && inside(row - k * dr, col - k * dc); ++k) {
      const size_t o = scan.Index(row - k * dr, col - k * dc);
      if (object[o] != 0 && scan.IsValid(o) && scan.point_scanner(o).norm() < r - tol) return true;
    }
    return false;
  };
  // Whether the surface k and k + 1 cells on along (dr, dc), extrapolated
  // back to the cell, lies beyond r for some k up to `radius`; the
  // extrapolation's noise grows with k: sqrt((k+1)^2 + k^2) range sigmas.
  const auto surface_beyond = [&](int row, int col, int dr, int dc, double r, double tol) {
    for (int k = 1; k <= radius; ++k) {
      const double b1 = behind(row + k * dr, col + k * dc), b2 = behind(row + (k + 1) * dr, col + (k + 1) * dc);
      const double spread = std::sqrt(static_cast<double>((k + 1) * (k + 1) + k * k) / 5.0);
      if (r < b1 - k * (b2 - b1) - spread * tol) return true;  // false when either is NaN
    }
    return false;
  };
  // Only the grid's rectangle around the object's cells can hold any.
  int row_lo = rows, row_hi = -1, col_lo = cols, col_hi = -1;
  for (size_t i = 0; i < object.size(); ++i) {
    if (object[i] == 0) continue;
    row_lo = std::min(row_lo, scan.RowOf(i));
    row_hi = std::max(row_hi, scan.RowOf(i));
    col_lo = std::min(col_lo, scan.ColOf(i));
    col_hi = std::max(col_hi, scan.ColOf(i));
  }
  if (row_hi < 0) return 0;
  const double step = LatticeStep(scan);
  constexpr int kLines[8][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}, {0, -1}, {-1, 0}, {-1, -1}, {-1, 1}};
  constexpr int kSilhouetteLines = 2;
  size_t found = 0;
#pragma omp parallel for schedule(static) reduction(+ : found)
  for (int col = std::max(0, col_lo - radius); col <= std::min(cols - 1, col_hi + radius); ++col) {
    for (int row = std::max(0, row_lo - radius); row <= std::min(rows - 1, row_hi + radius); ++row) {
      const double r = behind(row, col);
      const size_t i = scan.Index(row, col);
      if (std::isnan(r) || (*out)[i] != 0) continue;
      const double tol = Tolerance(options, r, step);
      int lines = 0;
      for (const auto& line : kLines) {
        lines += object_before(row, col, line[0], line[1], r, tol) && surface_beyond(row, col, line[0], line[1], r, tol);
      }
      if (lines >= kSilhouetteLines) {
        (*out)[i] = 1;
        ++found;
      }
    }
  }
  return found;
}

}  // namespace

size_t MarkSilhouetteMixedPixels(const ScanSet& scans, const std::vector<std::vector<uint8_t>>& object,
                                 const MixedPixelOptions& options, int radius,
                                 std::vector<std::vector<uint8_t>>* mixed) {
  size_t added = 0;
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    added += MarkSilhouetteMixedPixels(scans.scans[s], object[s], options, radius, &(*mixed)[s]);
  }
  return added;
}

ScanSet WithoutMixedPixels(const ScanSet& scans, const MixedPixelOptions& options,
                           size_t* removed) {
  const std::vector<std::vector<uint8_t>> mixed = FindMixedPixels(scans, options, removed);
  ScanSet out = scans;
  for (size_t s = 0; s < out.scans.size(); ++s) {
    for (size_t i = 0; i < mixed[s].size(); ++i) {
      if (mixed[s][i] != 0) out.scans[s].SetMissing(i);
    }
  }
  return out;
}

}  // namespace edgefit
