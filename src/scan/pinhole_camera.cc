#include "edgefit/scan/pinhole_camera.h"

#include <cmath>

namespace edgefit {
namespace {

// (x'', y'') of the normalized (x', y'): the header's distortion.
Eigen::Vector2d Distort(const std::array<double, 8>& d, double x, double y) {
  const double r2 = x * x + y * y;
  const double radial = (1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]))) /
                        (1.0 + r2 * (d[5] + r2 * (d[6] + r2 * d[7])));
  return {x * radial + 2.0 * d[2] * x * y + d[3] * (r2 + 2.0 * x * x),
          y * radial + d[2] * (r2 + 2.0 * y * y) + 2.0 * d[3] * x * y};
}

}  // namespace

bool PinholeCamera::HasDistortion() const {
  for (const double k : distortion) {
    if (k != 0.0) return true;
  }
  return false;
}

bool PinholeCamera::IsValid(std::string* error) const {
  auto fail = [error](const char* what) {
    if (error != nullptr) *error = what;
    return false;
  };
  if (!(std::isfinite(fx) && std::isfinite(fy) && fx > 0.0 && fy > 0.0)) {
    return fail("focal lengths fx, fy must be finite and > 0 [px]");
  }
  if (!(std::isfinite(cx) && std::isfinite(cy))) return fail("principal point cx, cy not finite");
  for (const double k : distortion) {
    if (!std::isfinite(k)) return fail("distortion coefficient not finite");
  }
  return true;
}

bool PinholeCamera::Project(const Eigen::Vector3d& p_camera, double* u, double* v) const {
  if (!(p_camera.z() > 0.0)) return false;
  const double x = p_camera.x() / p_camera.z(), y = p_camera.y() / p_camera.z();
  if (!HasDistortion()) {
    *u = fx * x + cx;
    *v = fy * y + cy;
    return true;
  }
  const Eigen::Vector2d d = Distort(distortion, x, y);
  *u = fx * d.x() + cx;
  *v = fy * d.y() + cy;
  return true;
}

Eigen::Vector3d PinholeCamera::Ray(double u, double v) const {
  const double xd = (u - cx) / fx, yd = (v - cy) / fy;
  if (!HasDistortion()) return {xd, yd, 1.0};
  // Fixed point x' = x'' - (distort(x') - x'): converges for the distortions
  // of real lenses within their image (a few iterations to 1e-9 px).
  double x = xd, y = yd;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector2d d = Distort(distortion, x, y);
    const double ex = d.x() - xd, ey = d.y() - yd;
    x -= ex;
    y -= ey;
    if (std::abs(ex) + std::abs(ey) < 1e-12) break;
  }
  return {x, y, 1.0};
}

}  // namespace edgefit
