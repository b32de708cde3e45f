// PinholeCamera: a depth camera's projection, the grid of a projective
// lattice (scan_lattice.h). Pixel (u, v) is column u, row v, the pixel's
// centre at integers (the ROS sensor_msgs/CameraInfo convention). In the
// camera's optical frame (x right, y down, z forward):
//   x' = x / z, y' = y / z                          (normalized coordinates)
//   (x'', y'') = distort(x', y')                    (identity without distortion)
//   u = fx x'' + cx, v = fy y'' + cy                [px]
// The distortion is OpenCV's, as ROS's plumb_bob (k1 k2 p1 p2 k3) and
// rational_polynomial (k1 k2 p1 p2 k3 k4 k5 k6) models write it:
//   r2 = x'^2 + y'^2
//   radial = (1 + k1 r2 + k2 r2^2 + k3 r2^3) / (1 + k4 r2 + k5 r2^2 + k6 r2^3)
//   x'' = x' radial + 2 p1 x' y' + p2 (r2 + 2 x'^2)
//   y'' = y' radial + p1 (r2 + 2 y'^2) + 2 p2 x' y'
// Unprojection inverts it by fixed-point iteration (as cv::undistortPoints).
#ifndef EDGEFIT_SCAN_PINHOLE_CAMERA_H_
#define EDGEFIT_SCAN_PINHOLE_CAMERA_H_

#include <Eigen/Core>
#include <array>
#include <string>

namespace edgefit {

struct PinholeCamera {
  double fx = 0.0, fy = 0.0;  // focal lengths [px]
  double cx = 0.0, cy = 0.0;  // principal point [px]
  // k1 k2 p1 p2 k3 k4 k5 k6; all zero: no distortion.
  std::array<double, 8> distortion{};

  bool HasDistortion() const;
  // Finite, positive focal lengths, finite principal point and distortion.
  bool IsValid(std::string* error) const;
  // (u, v) [px] of a point with z > 0 in the optical frame; false for z <= 0.
  bool Project(const Eigen::Vector3d& p_camera, double* u, double* v) const;
  // The ray through pixel (u, v): (x', y', 1), the point at depth z = 1.
  Eigen::Vector3d Ray(double u, double v) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_PINHOLE_CAMERA_H_
