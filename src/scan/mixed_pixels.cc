#include "edgefit/scan/mixed_pixels.h"

#include <algorithm>
#include <cmath>

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

std::vector<uint8_t> FindMixedPixels(const OrganizedScan& scan, const MixedPixelOptions& options) {
  std::vector<uint8_t> mixed(scan.size(), 0);
  if (!scan.organized()) return mixed;
  // Lines along which each cell is mixed.
  std::vector<uint8_t> line_count(scan.size(), 0);
  const int rows = scan.rows(), cols = scan.cols();
  // Range of a cell, NaN when missing or off the grid.
  auto range = [&](int row, int col) -> double {
    if (row < 0 || row >= rows || col < 0 || col >= cols) return std::nan("");
    const size_t i = scan.Index(row, col);
    return scan.IsValid(i) ? static_cast<double>(scan.point_scanner(i).norm()) : std::nan("");
  };
  // The cell's spacing is range * step (0 without a lattice).
  const double step =
      std::max(std::abs(scan.lattice().row_step()), std::abs(scan.lattice().col_step()));

  // Row, column and the two diagonals.
  constexpr int kLines[4][2] = {{0, 1}, {1, 0}, {1, 1}, {1, -1}};
#pragma omp parallel for schedule(static)
  for (int col = 0; col < cols; ++col) {
    for (int row = 0; row < rows; ++row) {
      const double r = range(row, col);
      if (std::isnan(r)) continue;
      const double tol = std::max(options.tolerance, options.tolerance_per_spacing * r * step);
      int lines = 0;
      for (const auto& line : kLines) {
        const int dr = line[0], dc = line[1];
        const double a1 = range(row - dr, col - dc), b1 = range(row + dr, col + dc);
        if (std::isnan(a1) || std::isnan(b1)) continue;
        if (!(r > std::min(a1, b1) + tol && r < std::max(a1, b1) - tol)) continue;
        const double a2 = range(row - 2 * dr, col - 2 * dc);
        const double b2 = range(row + 2 * dr, col + 2 * dc);
        const double from_a = std::isnan(a2) ? a1 : 2.0 * a1 - a2;
        const double from_b = std::isnan(b2) ? b1 : 2.0 * b1 - b2;
        lines += std::abs(r - from_a) > tol && std::abs(r - from_b) > tol;
      }
      line_count[scan.Index(row, col)] = static_cast<uint8_t>(lines);
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
