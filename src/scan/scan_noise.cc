#include "edgefit/scan/scan_noise.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "edgefit/core/median.h"

namespace edgefit {
namespace {

constexpr double kMadToSigma = 1.4826;

// The distance of cell (r, c) to the plane through its window's other valid
// cells [m]; NaN with fewer than min_neighbours of them.
double PlaneDistance(const OrganizedScan& scan, int r, int c, const ScanNoiseOptions& options) {
  const Eigen::Vector3d p = scan.point_scanner(scan.Index(r, c)).cast<double>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  int n = 0;
  const int w = options.half_window;
  for (int dc = -w; dc <= w; ++dc) {
    const int cc = c + dc;
    if (cc < 0 || cc >= scan.cols()) continue;
    for (int dr = -w; dr <= w; ++dr) {
      const int rr = r + dr;
      if (rr < 0 || rr >= scan.rows() || (dr == 0 && dc == 0)) continue;
      const size_t i = scan.Index(rr, cc);
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d q = scan.point_scanner(i).cast<double>() - p;  // centred on p
      sum += q;
      outer += q * q.transpose();
      ++n;
    }
  }
  if (n < options.min_neighbours) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d mean = sum / n;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(outer / n - mean * mean.transpose());
  return std::abs(eig.eigenvectors().col(0).dot(mean));  // p is the origin
}

}  // namespace

bool ScanNoiseOptions::IsValid(std::string* error) const {
  if (stride < 1) *error = "stride must be >= 1";
  else if (max_cells < 1) *error = "max_cells must be >= 1";
  else if (half_window < 1) *error = "half_window must be >= 1";
  else if (min_neighbours < 3) *error = "min_neighbours must be >= 3";
  else if (!(bin > 0.0)) *error = "bin must be > 0";
  else if (min_per_bin < 1) *error = "min_per_bin must be >= 1";
  else return true;
  return false;
}

double ScanNoise::At(double range) const {
  if (sigma.empty()) return median_sigma;
  const int k = std::clamp(static_cast<int>(range / bin), 0, static_cast<int>(sigma.size()) - 1);
  for (int d = 0; d < static_cast<int>(sigma.size()); ++d) {
    for (const int b : {k - d, k + d}) {
      if (b >= 0 && b < static_cast<int>(sigma.size()) && std::isfinite(sigma[b])) return sigma[b];
    }
  }
  return median_sigma;
}

ScanNoise EstimateScanNoise(const ScanSet& scans, const ScanNoiseOptions& options) {
  ScanNoise noise;
  noise.bin = options.bin;
  std::vector<std::vector<double>> per_bin;
  std::vector<double> all;
  for (const OrganizedScan& scan : scans.scans) {
    if (!scan.organized()) continue;
    size_t valid = 0;
    for (size_t i = 0; i < scan.size(); ++i) valid += scan.IsValid(i);
    const size_t stride = std::max({static_cast<size_t>(options.stride), size_t{1},
                                    valid / static_cast<size_t>(options.max_cells)});
    std::vector<size_t> cells;
    valid = 0;
    for (size_t i = 0; i < scan.size(); ++i) {
      if (scan.IsValid(i) && valid++ % stride == 0) cells.push_back(i);
    }
    std::vector<double> distance(cells.size());
#pragma omp parallel for schedule(static)
    for (int64_t k = 0; k < static_cast<int64_t>(cells.size()); ++k) {
      const size_t i = cells[static_cast<size_t>(k)];
      distance[static_cast<size_t>(k)] = PlaneDistance(scan, scan.RowOf(i), scan.ColOf(i), options);
    }
    for (size_t k = 0; k < cells.size(); ++k) {
      if (!std::isfinite(distance[k])) continue;
      const double range = scan.point_scanner(cells[k]).cast<double>().norm();
      const size_t b = static_cast<size_t>(range / options.bin);
      if (b >= per_bin.size()) per_bin.resize(b + 1);
      per_bin[b].push_back(distance[k]);
      all.push_back(distance[k]);
    }
  }
  noise.measured = all.size();
  if (all.empty()) return noise;
  noise.median_sigma = kMadToSigma * MedianInPlace(&all);
  noise.sigma.assign(per_bin.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t b = 0; b < per_bin.size(); ++b) {
    if (static_cast<int>(per_bin[b].size()) >= options.min_per_bin) {
      noise.sigma[b] = kMadToSigma * MedianInPlace(&per_bin[b]);
    }
  }
  return noise;
}

}  // namespace edgefit
