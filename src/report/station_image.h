// What each station saw, as an image for papers and batch summaries: the
// scan's grid, around the cells that hold the model's surroundings, each
// cell coloured by its point's distance to the fitted model (the report's
// colours: green at 0 through red at residual_scale, grey beyond
// not_modelled, white where the scanner got no return). Up is up and left
// is left as the scanner looked.
#ifndef EDGEFIT_REPORT_STATION_IMAGE_H_
#define EDGEFIT_REPORT_STATION_IMAGE_H_

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/report/fit_report.h"
#include "edgefit/scan/organized_scan.h"
#include "model_distance.h"

namespace edgefit {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first
};

// The report's colour of a point at `distance` [m] from the model (the
// page colours by a table of it).
std::array<uint8_t, 3> ResidualColour(double distance, const FitReportOptions& options);

// The image of `scan` placed at T_world_scanner: the grid's cells whose
// points lie in `crop` (world), with a margin of 5 % (at most
// options.max_image_size pixels a side, every k-th cell). Empty when no
// point of the scan lies in the crop, or the scan has no grid (a PLY cloud).
RgbImage StationImage(const OrganizedScan& scan, const Pose& T_world_scanner,
                      const ModelDistance& distance, const Eigen::Vector3d& origin,
                      const Eigen::AlignedBox3d& crop, const FitReportOptions& options);

// The image as PNG bytes (libpng).
Status EncodePng(const RgbImage& image, std::string* png);

}  // namespace edgefit

#endif  // EDGEFIT_REPORT_STATION_IMAGE_H_
