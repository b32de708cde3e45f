// Rigid transforms. `T_a_b` maps coordinates in frame b to frame a
// (DESIGN.md conventions); all lengths in metres, angles in radians.
#ifndef EDGEFIT_CORE_POSE_H_
#define EDGEFIT_CORE_POSE_H_

#include <Eigen/Geometry>
#include <array>

namespace edgefit {

using Pose = Eigen::Isometry3d;

// URDF convention: R = Rz(yaw) * Ry(pitch) * Rx(roll), fixed axes X, Y, Z.
Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy);
// Inverse of RotationFromRpy; pitch in [-pi/2, pi/2].
Eigen::Vector3d RpyFromRotation(const Eigen::Matrix3d& R);
// T from a translation and URDF roll-pitch-yaw.
Pose PoseFromXyzRpy(const Eigen::Vector3d& xyz, const Eigen::Vector3d& rpy);
// A pose on the floor plane: translation (x, y, 0), rotation about +Z by yaw.
Pose PoseFromXyYaw(double x, double y, double yaw);
// The 4x4 matrix of T, row by row (the JSON layout of result.json and the
// truth file: nlohmann::json takes it as nested arrays).
std::array<std::array<double, 4>, 4> PoseRows(const Pose& T);

}  // namespace edgefit

#endif  // EDGEFIT_CORE_POSE_H_
