// ScanLattice: the grid of one organized scan. It maps any point to its
// (row, col) in O(1) and a cell back to its ray. Two models:
//
// Angular: a terrestrial scanner's (elevation, azimuth) grid (paper Sec.
// 4.1, Fig. 5a). The lattice frame L is the scanner frame rotated so that
// the scanner's vertical rotation axis is +Z (R_scanner_lattice absorbs
// tilt). In L:
//   azimuth   = atan2(y, x)              [rad], one value per column
//   elevation = atan2(z, sqrt(x^2+y^2))  [rad], one value per row
// Azimuths are unwrapped along the columns (monotonic), so a full 360 degree
// scan has no seam. The inverse map uses the robust linear fit
//   col ~ (azimuth - azimuth0) / azimuth_step, row ~ (elevation - elevation0) / elevation_step
// with per-row/col tables for the exact angles.
//
// Projective: a depth camera's pixel grid (pinhole_camera.h): column u and
// row v of the point's projection, in the camera's optical frame (x right,
// y down, z forward); points at z <= 0 are behind the camera.
//
// Both give the signed angular step between adjacent rows and columns
// (row_step, col_step [rad]): the angular lattice's mean steps; for a camera
// those at its principal point (-1/fy, -1/fx: rows go down, columns right,
// where the angular grid's elevation and azimuth go up and left). Off the
// axis a camera's pixels subtend less (cos^2 of the angle off it): the
// steps are the largest, which is what the windows sized by them need.
#ifndef EDGEFIT_SCAN_SCAN_LATTICE_H_
#define EDGEFIT_SCAN_SCAN_LATTICE_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/scan/pinhole_camera.h"

namespace edgefit {

class ScanLattice {
 public:
  enum class Model { kAngular, kProjective };

  ScanLattice() = default;
  // An angular lattice from its per-row elevations and per-column azimuths
  // [rad], both monotonic, and the scanner tilt R_scanner_lattice.
  ScanLattice(std::vector<double> row_elevations, std::vector<double> col_azimuths,
              const Eigen::Matrix3d& R_scanner_lattice = Eigen::Matrix3d::Identity());
  // A projective lattice: rows x cols pixels of `camera` (valid intrinsics).
  ScanLattice(int rows, int cols, const PinholeCamera& camera);

  Model model() const { return model_; }
  bool valid() const { return rows_ > 0 && cols_ > 0; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  // "angular" or "projective".
  const char* ModelName() const;

  // Signed step between adjacent rows / columns [rad] (the header).
  double row_step() const { return row_step_; }
  double col_step() const { return col_step_; }

  // Angular lattices: the row's elevation and the column's azimuth [rad],
  // the scanner's tilt, and whether the columns close the full circle
  // (|cols * col_step| ~ 2 pi: column cols-1 neighbours column 0 and
  // projection wraps around; never for a camera).
  double elevation(int row) const { return row_elevations_[row]; }
  double azimuth(int col) const { return col_azimuths_[col]; }
  const Eigen::Matrix3d& R_scanner_lattice() const { return R_scanner_lattice_; }
  bool full_circle() const { return full_circle_; }
  // Projective lattices: the camera.
  const PinholeCamera& camera() const { return camera_; }

  // Fractional (row, col) of a point in the scanner frame; false when it
  // falls outside the grid (by more than half a step), at the scanner origin
  // or behind the camera. O(1).
  bool Project(const Eigen::Vector3d& p_scanner, double* row, double* col) const;
  // Nearest cell of a point in the scanner frame; false outside the grid. O(1).
  bool ProjectToCell(const Eigen::Vector3d& p_scanner, int* row, int* col) const;
  // Unit ray direction of cell (row, col) in the scanner frame.
  Eigen::Vector3d Direction(int row, int col) const;
  // Angular lattices: the lattice-frame angles of a scanner-frame point
  // [rad]; the azimuth is not yet unwrapped to the column range.
  void Angles(const Eigen::Vector3d& p_scanner, double* elevation, double* azimuth) const;

 private:
  Model model_ = Model::kAngular;
  int rows_ = 0, cols_ = 0;
  double row_step_ = 0.0, col_step_ = 0.0;
  // Angular.
  std::vector<double> row_elevations_;
  std::vector<double> col_azimuths_;
  Eigen::Matrix3d R_scanner_lattice_ = Eigen::Matrix3d::Identity();
  double elevation0_ = 0.0, azimuth0_ = 0.0;
  double azimuth_center_ = 0.0;  // middle of the column range [rad]
  bool full_circle_ = false;
  // Projective.
  PinholeCamera camera_;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_SCAN_LATTICE_H_
