// Private: a point list taken from a depth camera's frame, put back on the
// camera's pixel grid (read_common.h).
#ifndef EDGEFIT_SRC_IO_CAMERA_GRID_H_
#define EDGEFIT_SRC_IO_CAMERA_GRID_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/io/camera_info.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {
namespace io_internal {

// Exporters of depth frames often drop the pixels without a depth and write
// the rest as a point list (a RealSense .ply, Open3D's clouds from a depth
// image). Each point, in the camera's optical frame (the scan's scanner
// frame), is projected through `camera`; a frame of that camera puts it on
// a pixel centre. *grid becomes the camera's height x width organized scan
// (row by row, the cloud's pose, intensities and colours), the pixels
// without a point missing. Fails, naming `what`, when more than
// kMaxOffCentreShare of the points fall outside the image or more than
// kMaxPixelOffset from a pixel centre, or two points share a pixel (not a
// frame of this camera, or one taken through other intrinsics).
Status GridOnCamera(const std::string& what, const CameraInfo& camera, const OrganizedScan& cloud,
                    OrganizedScan* grid);

constexpr double kMaxPixelOffset = 0.05;     // [px]
constexpr double kMaxOffCentreShare = 0.01;  // of the points

}  // namespace io_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_IO_CAMERA_GRID_H_
