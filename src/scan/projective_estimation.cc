// A depth camera's projective lattice estimated from its points
// (lattice_estimation.h): the pinhole's columns and rows are linear in x/z
// and y/z, u = fx x/z + cx and v = fy y/z + cy, so two robust straight-line
// fits over the valid points give fx, cx and fy, cy.
#include <algorithm>
#include <cmath>
#include <vector>

#include "edgefit/core/median.h"
#include "edgefit/scan/lattice_estimation.h"

namespace edgefit {
namespace {

// Least squares pixel = f * a + c over (a, pixel) pairs, then again without
// the pairs more than 3 median absolute residuals (at least 0.05 px) off.
// rms: of the kept pairs' residuals [px]. False for fewer than 2 pairs or
// no spread in a.
bool RobustLine(const std::vector<double>& a, const std::vector<double>& pixel, double* f,
                double* c, double* rms) {
  std::vector<char> keep(a.size(), 1);
  for (int pass = 0; pass < 3; ++pass) {
    double n = 0, sa = 0, sp = 0, saa = 0, sap = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      if (!keep[i]) continue;
      n += 1;
      sa += a[i];
      sp += pixel[i];
      saa += a[i] * a[i];
      sap += a[i] * pixel[i];
    }
    const double var = saa - sa * sa / std::max(n, 1.0);
    if (n < 2 || !(var > 0.0)) return false;
    *f = (sap - sa * sp / n) / var;
    *c = (sp - *f * sa) / n;
    std::vector<double> residuals;
    residuals.reserve(a.size());
    double sum_sq = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
      const double r = std::abs(pixel[i] - (*f * a[i] + *c));
      if (keep[i]) sum_sq += r * r;
      residuals.push_back(r);
    }
    *rms = std::sqrt(sum_sq / n);
    std::vector<double> sorted = residuals;
    const double limit = std::max(0.05, 3.0 * MedianInPlace(&sorted));
    for (size_t i = 0; i < a.size(); ++i) keep[i] = residuals[i] <= limit;
  }
  return true;
}

}  // namespace

Status EstimateProjectiveLattice(const OrganizedScan& scan, const LatticeOptions& options,
                                 ScanLattice* lattice, double* rms_px) {
  // At most ~200 k points, spread over the grid: the fits need few.
  const size_t valid = scan.CountValid();
  const size_t stride = std::max<size_t>(1, valid / 200000);
  std::vector<double> x, u, y, v;
  size_t seen = 0, in_front = 0;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (!scan.IsValid(i)) continue;
    const Eigen::Vector3d p = scan.point_scanner(i).cast<double>();
    if (p.z() > 0.0) ++in_front;
    if (seen++ % stride != 0 || !(p.z() > 0.0)) continue;
    x.push_back(p.x() / p.z());
    u.push_back(scan.ColOf(i));
    y.push_back(p.y() / p.z());
    v.push_back(scan.RowOf(i));
  }
  if (static_cast<double>(in_front) < options.min_in_front_share * static_cast<double>(valid)) {
    return Status::Error("not a camera's frame: " + std::to_string(valid - in_front) + " of " +
                         std::to_string(valid) + " points lie behind its optical axis (z <= 0)");
  }
  PinholeCamera camera;
  double rms_u = 0.0, rms_v = 0.0;
  if (!RobustLine(x, u, &camera.fx, &camera.cx, &rms_u) ||
      !RobustLine(y, v, &camera.fy, &camera.cy, &rms_v)) {
    return Status::Error("too few points spread over the frame to estimate its camera");
  }
  std::string error;
  if (!camera.IsValid(&error)) {
    return Status::Error("the points do not lie on a pinhole camera's grid (" + error + ")");
  }
  *rms_px = std::max(rms_u, rms_v);
  *lattice = ScanLattice(scan.rows(), scan.cols(), camera);
  return Status::Ok();
}

}  // namespace edgefit
