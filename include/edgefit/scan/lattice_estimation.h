// Estimation of a scan's ScanLattice from its points (DESIGN.md, Formats:
// "the lattice of a real scan is not given"). Which model: a depth camera's
// frame (organized in its optical frame, every point in front of it: z > 0)
// lies on a pinhole's grid, u = fx x/z + cx, v = fy y/z + cy; the model
// whose fit leaves the smaller residual is taken (LatticeOptions::model).
//
// Projective: two robust straight-line fits, u on x/z and v on y/z, over
// the valid points (outliers beyond 3 median residuals dropped).
//
// Angular:
// 1. Tilt: every column of a TLS scan is one position of the scanner head, so
//    its rays span a plane through the origin that contains the rotation axis
//    a. The plane normal n_c (smallest eigenvector of sum d d^T over the
//    column's unit directions d) is perpendicular to a, hence
//    a = argmin_a sum_c (n_c . a)^2 = smallest eigenvector of sum_c n_c n_c^T.
//    R_scanner_lattice = [x_L y_L a] with x_L the scanner x projected off a.
// 2. Angles in the lattice frame: column azimuth = circular median over the
//    column's points, row elevation = median over the row's points. Medians
//    ignore range noise (it does not change a direction) and stray points.
// 3. Azimuths are unwrapped along the columns with the median adjacent step,
//    so a full 360 degree scan has no seam.
// 4. Rows / columns without enough points are interpolated linearly between
//    their known neighbours, or extrapolated with the median step at the ends.
#ifndef EDGEFIT_SCAN_LATTICE_ESTIMATION_H_
#define EDGEFIT_SCAN_LATTICE_ESTIMATION_H_

#include <string>

#include "edgefit/core/status.h"
#include "edgefit/scan/scan_lattice.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct LatticeOptions {
  // The lattice's model; kAuto: projective when at least
  // min_in_front_share of the valid points lie in front of the frame's xy
  // plane and the projective fit's RMS residual is within
  // max_projective_rms_px, angular otherwise.
  enum class Model { kAuto, kAngular, kProjective };
  Model model = Model::kAuto;
  double min_in_front_share = 0.99;
  double max_projective_rms_px = 0.25;  // [px]
  // Fewer valid points than this in the scan: fail (too sparse to trust).
  int min_valid_points = 50;
  // A row or column with fewer valid points is treated as missing and
  // interpolated from its neighbours.
  int min_points_per_line = 1;
  // Estimate the scanner tilt (rotation axis); false: lattice frame = scanner frame.
  bool estimate_tilt = true;
  // A column takes part in the tilt estimate only if it has this many points
  // spanning at least min_column_span_rad in elevation.
  int min_points_per_tilt_column = 5;
  double min_column_span_rad = 0.05;  // [rad] ~3 degrees
  // The normals must spread over this azimuth range for the axis to be
  // observable (a narrow window cannot tell tilt from azimuth) [rad].
  double min_tilt_azimuth_span_rad = 0.1;
  // A tilt estimate above this is not believed (lattice frame = scanner frame) [rad].
  double max_tilt_rad = 0.35;  // ~20 degrees

  bool IsValid(std::string* error) const;
};

// Estimates `lattice` of an organized scan (angular: rows = elevation, cols
// = azimuth; projective: rows = v, cols = u). Fails for an unorganized scan,
// or one with fewer than 2 rows / columns that hold points or fewer than
// min_valid_points valid points.
Status EstimateLattice(const OrganizedScan& scan, const LatticeOptions& options,
                       ScanLattice* lattice);

// The projective lattice alone (fx, fy, cx, cy); *rms_px: the fits' larger
// RMS residual [px]. Fails when fewer than min_in_front_share of the points
// lie in front of the frame or the fits find no positive focal lengths.
Status EstimateProjectiveLattice(const OrganizedScan& scan, const LatticeOptions& options,
                                 ScanLattice* lattice, double* rms_px);

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_LATTICE_ESTIMATION_H_
