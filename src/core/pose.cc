#include "edgefit/core/pose.h"

#include <cmath>

namespace edgefit {

Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d RpyFromRotation(const Eigen::Matrix3d& R) {
  // R = Rz(y) Ry(p) Rx(r): R(2,0) = -sin(p), hypot(R(0,0), R(1,0)) = cos(p).
  // atan2 keeps full precision near +-90 degrees, where asin(-R(2,0)) does not.
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  double roll, yaw;
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {  // Gimbal lock: only roll - yaw (or roll + yaw) is defined; put it all in yaw.
    roll = 0.0;
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  return Eigen::Vector3d(roll, pitch, yaw);
}

Pose PoseFromXyzRpy(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy) {
  Pose T = Pose::Identity();
  T.linear() = RotationFromRpy(rpy);
  T.translation() = xyz;
  return T;
}

Pose PoseFromXyYaw(double x, double y, double yaw) {
  return PoseFromXyzRpy(Eigen::Vector3d(x, y, 0.0), Eigen::Vector3d(0.0, 0.0, yaw));
}

std::array<std::array<double, 4>, 4> PoseRows(const Pose& T) {
  std::array<std::array<double, 4>, 4> rows;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c)
      rows[static_cast<size_t>(r)][static_cast<size_t>(c)] = T.matrix()(r, c);
  }
  return rows;
}

}  // namespace edgefit
