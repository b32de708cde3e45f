// A depth camera's frame as a 16-bit grey PNG (the ROS convention for
// 16UC1 depth images: one depth per pixel along the optical axis, in
// millimetres, 0 where the camera measured nothing), with the camera's
// intrinsics (ReadOptions::camera, a ROS camera_info file: camera_info.h).
// Pixel (u, v) becomes the point z * PinholeCamera::Ray(u, v) in the
// camera's optical frame (x right, y down, z forward), z the depth times
// ReadOptions::depth_scale; the scan is organized (rows = v, cols = u, the
// file's order row by row), its lattice the camera's projective one, and
// its pose the identity: the world frame of such a frame is the camera's.
// A frame with a pose is written as an organized PCD with VIEWPOINT.
#ifndef EDGEFIT_IO_DEPTH_PNG_H_
#define EDGEFIT_IO_DEPTH_PNG_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/io/io_options.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

// Appends the frame of `path` to `scans`. Fails with one line naming the
// file when it is not a readable PNG, not 16-bit grey, has no camera
// (options.camera empty) or another size than the camera's, or holds no
// depth.
Status ReadDepthPng(const std::string& path, const ReadOptions& options, ScanSet* scans);

}  // namespace edgefit

#endif  // EDGEFIT_IO_DEPTH_PNG_H_
