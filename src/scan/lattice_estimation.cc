#include "edgefit/scan/lattice_estimation.h"

#include <glog/logging.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/core/angles.h"
#include "edgefit/core/median.h"

namespace edgefit {
namespace {

// Rotation axis of the scanner head in the scanner frame (header comment, 1).
// Returns false when the columns cannot observe it.
bool EstimateAxis(const OrganizedScan& scan, const LatticeOptions& options,
                  Eigen::Vector3d* axis) {
  const int rows = scan.rows(), cols = scan.cols();
  std::vector<Eigen::Vector3d> normals(static_cast<size_t>(cols), Eigen::Vector3d::Zero());
  const double min_span_sq = std::pow(std::sin(options.min_column_span_rad), 2);
#pragma omp parallel for schedule(dynamic, 16)
  for (int c = 0; c < cols; ++c) {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    int n = 0;
    for (int r = 0; r < rows; ++r) {
      const size_t i = scan.Index(r, c);
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3d d = scan.point_scanner(i).cast<double>().normalized();
      scatter += d * d.transpose();
      ++n;
    }
    if (n < options.min_points_per_tilt_column) continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(scatter / n);
    // The middle eigenvalue measures the in-plane spread of the rays.
    if (eig.eigenvalues()(1) < min_span_sq / 4.0) continue;
    normals[static_cast<size_t>(c)] = eig.eigenvectors().col(0);
  }
  const double min_spread_sq = std::pow(std::sin(options.min_tilt_azimuth_span_rad), 2);
  std::vector<double> weights(normals.size(), 1.0);
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    double total = 0.0;
    for (size_t c = 0; c < normals.size(); ++c) {
      if (normals[c].isZero()) continue;
      scatter += weights[c] * normals[c] * normals[c].transpose();
      total += weights[c];
    }
    if (total < 3.0) return false;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(scatter / total);
    if (eig.eigenvalues()(1) < min_spread_sq / 4.0) return false;
    *axis = eig.eigenvectors().col(0);
    if (axis->z() < 0.0) *axis = -*axis;
    // Second pass: drop columns whose plane disagrees with the axis (mixed
    // or stray points bend a column's plane), threshold 3 x median residual.
    std::vector<double> residuals;
    for (const auto& n : normals) {
      if (!n.isZero()) residuals.push_back(std::abs(n.dot(*axis)));
    }
    const double limit = 3.0 * MedianInPlace(&residuals) + 1e-9;
    for (size_t c = 0; c < normals.size(); ++c) {
      weights[c] = normals[c].isZero() || std::abs(normals[c].dot(*axis)) <= limit ? 1.0 : 0.0;
    }
  }
  return true;
}

// Fills the entries of `angles` whose `known` flag is false: linear
// interpolation inside, extrapolation with `step` at the ends. With `wrap`,
// known values are first unwrapped (2 pi) along the index.
Status FillLine(const char* what, bool wrap, const std::vector<char>& known,
                std::vector<double>* angles) {
  const int n = static_cast<int>(angles->size());
  std::vector<int> idx;
  for (int i = 0; i < n; ++i) {
    if (known[static_cast<size_t>(i)]) idx.push_back(i);
  }
  if (idx.empty() || (n > 1 && idx.size() < 2)) {
    return Status::Error(std::string("fewer than 2 ") + what + " hold points");
  }
  if (n == 1) return Status::Ok();
  auto diff = [wrap](double a, double b) {
    return wrap ? std::remainder(b - a, kTwoPi) : b - a;
  };
  // Median step over pairs of known lines, per index.
  std::vector<double> steps;
  for (size_t k = 1; k < idx.size(); ++k) {
    if (idx[k] - idx[k - 1] == 1) steps.push_back(diff((*angles)[idx[k - 1]], (*angles)[idx[k]]));
  }
  if (steps.empty()) {
    for (size_t k = 1; k < idx.size(); ++k) {
      steps.push_back(diff((*angles)[idx[k - 1]], (*angles)[idx[k]]) / (idx[k] - idx[k - 1]));
    }
  }
  const double step = MedianInPlace(&steps);
  if (step == 0.0) return Status::Error(std::string("zero angular step between ") + what);
  auto& a = *angles;
  for (size_t k = 1; k < idx.size(); ++k) {
    const int i = idx[k - 1], j = idx[k];
    if (wrap) {
      const double expected = (j - i) * step;
      a[j] = a[i] + expected + std::remainder(a[j] - a[i] - expected, kTwoPi);
    }
    for (int m = i + 1; m < j; ++m) a[m] = a[i] + (a[j] - a[i]) * (m - i) / (j - i);
  }
  for (int m = 0; m < idx.front(); ++m) a[m] = a[idx.front()] - (idx.front() - m) * step;
  for (int m = idx.back() + 1; m < n; ++m) a[m] = a[idx.back()] + (m - idx.back()) * step;
  // The lattice must be strictly monotonic; if stray medians broke that,
  // fall back to the robust line a0 + step * i with a0 = median(a_i - step i).
  bool monotonic = true;
  for (int i = 1; i < n; ++i) monotonic &= (a[i] - a[i - 1]) * step > 0.0;
  if (!monotonic) {
    std::vector<double> offsets;
    for (int i : idx) offsets.push_back(a[i] - step * i);
    const double a0 = MedianInPlace(&offsets);
    LOG(WARNING) << "lattice " << what << " not monotonic; using a linear lattice";
    for (int i = 0; i < n; ++i) a[i] = a0 + step * i;
  }
  return Status::Ok();
}

}  // namespace

bool LatticeOptions::IsValid(std::string* error) const {
  if (min_valid_points < 3) *error = "min_valid_points must be >= 3";
  else if (!(min_in_front_share >= 0.0 && min_in_front_share <= 1.0))
    *error = "min_in_front_share must be in [0, 1]";
  else if (!(max_projective_rms_px > 0.0)) *error = "max_projective_rms_px must be > 0";
  else if (min_points_per_line < 1) *error = "min_points_per_line must be >= 1";
  else if (!(max_tilt_rad >= 0.0)) *error = "max_tilt_rad must be >= 0";
  else return true;
  return false;
}

Status EstimateLattice(const OrganizedScan& scan, const LatticeOptions& options,
                       ScanLattice* lattice) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("lattice options: " + error);
  if (!scan.organized()) return Status::Error("an unorganized cloud has no lattice");
  const size_t valid = scan.CountValid();
  if (valid < static_cast<size_t>(options.min_valid_points)) {
    return Status::Error("too few valid points to estimate the lattice (" +
                         std::to_string(valid) + " < " +
                         std::to_string(options.min_valid_points) + ")");
  }
  using Model = LatticeOptions::Model;
  if (options.model != Model::kAngular) {
    double rms_px = 0.0;
    const Status projective = EstimateProjectiveLattice(scan, options, lattice, &rms_px);
    if (options.model == Model::kProjective) return projective;
    if (projective.ok() && rms_px <= options.max_projective_rms_px) return Status::Ok();
  }
  Eigen::Matrix3d R_scanner_lattice = Eigen::Matrix3d::Identity();
  Eigen::Vector3d axis;
  if (options.estimate_tilt && EstimateAxis(scan, options, &axis)) {
    if (std::acos(std::min(1.0, axis.z())) <= options.max_tilt_rad) {
      const Eigen::Vector3d x =
          (Eigen::Vector3d::UnitX() - axis.x() * axis).normalized();
      R_scanner_lattice.col(0) = x;
      R_scanner_lattice.col(1) = axis.cross(x);
      R_scanner_lattice.col(2) = axis;
    } else {
      LOG(WARNING) << "estimated scanner tilt beyond max_tilt_rad; ignoring it";
    }
  }
  const Eigen::Matrix3f R_lattice_scanner = R_scanner_lattice.transpose().cast<float>();
  const int rows = scan.rows(), cols = scan.cols();
  // Lattice-frame elevation of every valid cell, kept for the row medians.
  std::vector<float> elevation(scan.size(), std::numeric_limits<float>::quiet_NaN());
  std::vector<double> col_azimuths(static_cast<size_t>(cols), 0.0);
  std::vector<char> col_known(static_cast<size_t>(cols), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (int c = 0; c < cols; ++c) {
    std::vector<double> azimuths;
    for (int r = 0; r < rows; ++r) {
      const size_t i = scan.Index(r, c);
      if (!scan.IsValid(i)) continue;
      const Eigen::Vector3f p = R_lattice_scanner * scan.point_scanner(i);
      const double xy = std::hypot(static_cast<double>(p.x()), static_cast<double>(p.y()));
      elevation[i] = static_cast<float>(std::atan2(static_cast<double>(p.z()), xy));
      azimuths.push_back(std::atan2(static_cast<double>(p.y()), static_cast<double>(p.x())));
    }
    if (static_cast<int>(azimuths.size()) < options.min_points_per_line) continue;
    // Circular median: angles relative to the first one, in (-pi, pi].
    const double ref = azimuths.front();
    for (double& a : azimuths) a = std::remainder(a - ref, kTwoPi);
    col_azimuths[static_cast<size_t>(c)] = ref + MedianInPlace(&azimuths);
    col_known[static_cast<size_t>(c)] = 1;
  }
  std::vector<double> row_elevations(static_cast<size_t>(rows), 0.0);
  std::vector<char> row_known(static_cast<size_t>(rows), 0);
#pragma omp parallel for schedule(dynamic, 16)
  for (int r = 0; r < rows; ++r) {
    std::vector<double> values;
    for (int c = 0; c < cols; ++c) {
      const float e = elevation[scan.Index(r, c)];
      if (!std::isnan(e)) values.push_back(e);
    }
    if (static_cast<int>(values.size()) < options.min_points_per_line) continue;
    row_elevations[static_cast<size_t>(r)] = MedianInPlace(&values);
    row_known[static_cast<size_t>(r)] = 1;
  }
  EDGEFIT_RETURN_IF_ERROR(FillLine("rows", false, row_known, &row_elevations));
  EDGEFIT_RETURN_IF_ERROR(FillLine("columns", true, col_known, &col_azimuths));
  *lattice = ScanLattice(std::move(row_elevations), std::move(col_azimuths),
                            R_scanner_lattice);
  return Status::Ok();
}

}  // namespace edgefit
