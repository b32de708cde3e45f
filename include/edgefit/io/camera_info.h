// A depth camera's intrinsics from a ROS camera_info YAML file (parsed with
// Debian's yaml-cpp). Two layouts are read:
//   - a sensor_msgs/CameraInfo message as `ros2 topic echo --once` or
//     rostopic print it: height, width, distortion_model, d, k (ROS 1: D, K);
//   - camera_calibration_parsers' calibration file: image_width,
//     image_height, camera_matrix {data}, distortion_model,
//     distortion_coefficients {data}.
// The intrinsics are K (fx = K[0], cx = K[2], fy = K[4], cy = K[5]) with the
// distortion d: plumb_bob (k1 k2 p1 p2 k3) or rational_polynomial (k1 k2 p1
// p2 k3 k4 k5 k6); any model with every coefficient zero is a pinhole (a
// rectified image, as depth images usually are). P and R are not read: a
// depth image is taken to be the image K and d describe.
#ifndef EDGEFIT_IO_CAMERA_INFO_H_
#define EDGEFIT_IO_CAMERA_INFO_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/scan/pinhole_camera.h"

namespace edgefit {

struct CameraInfo {
  int width = 0, height = 0;  // [px]
  PinholeCamera camera;
  std::string distortion_model;  // as written ("" when absent)
  std::string source;            // the file it was read from

  bool empty() const { return width == 0; }
};

// Reads `path`. Fails with one line naming the file on a missing or
// malformed file, missing or non-positive width / height, a K that is not 9
// finite numbers with positive focal lengths, or a distortion model other
// than plumb_bob / rational_polynomial with non-zero coefficients.
Status ReadCameraInfo(const std::string& path, CameraInfo* info);

}  // namespace edgefit

#endif  // EDGEFIT_IO_CAMERA_INFO_H_
