#include "camera_grid.h"

#include <cmath>
#include <cstdio>
#include <utility>

namespace edgefit {
namespace io_internal {

Status GridOnCamera(const std::string& what, const CameraInfo& camera, const OrganizedScan& cloud,
                    OrganizedScan* grid) {
  OrganizedScan out(camera.height, camera.width);
  out.set_organized(true);
  out.set_file_order(OrganizedScan::FileOrder::kRowMajor);
  out.set_T_world_scanner(cloud.T_world_scanner());
  if (cloud.has_color()) out.EnableColor();
  size_t points = 0, off_centre = 0, shared = 0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.IsValid(i)) continue;
    ++points;
    double u, v;
    if (!camera.camera.Project(cloud.point_scanner(i).cast<double>(), &u, &v)) {
      ++off_centre;
      continue;
    }
    const double col = std::round(u), row = std::round(v);
    if (std::abs(u - col) > kMaxPixelOffset || std::abs(v - row) > kMaxPixelOffset || col < 0 ||
        row < 0 || col >= camera.width || row >= camera.height) {
      ++off_centre;
      continue;
    }
    const size_t cell = out.Index(static_cast<int>(row), static_cast<int>(col));
    if (out.IsValid(cell)) {
      ++shared;
      continue;
    }
    out.SetPoint(cell, cloud.point_scanner(i), cloud.intensity(i));
    if (cloud.has_color()) out.SetColor(cell, cloud.color(i));
  }
  if (static_cast<double>(off_centre) > kMaxOffCentreShare * static_cast<double>(points) ||
      shared > 0) {
    char line[400];
    std::snprintf(line, sizeof(line),
                  ": a point list, not a frame of the camera in %s: %zu of its %zu points fall "
                  "outside the %d x %d image or more than %.2f px from a pixel centre, %zu on a "
                  "pixel another point took (points in the camera's optical frame, from a depth "
                  "image taken with these intrinsics, are gridded)",
                  camera.source.c_str(), off_centre, points, camera.width, camera.height,
                  kMaxPixelOffset, shared);
    return Status::Error(what + line);
  }
  *grid = std::move(out);
  return Status::Ok();
}

}  // namespace io_internal
}  // namespace edgefit
