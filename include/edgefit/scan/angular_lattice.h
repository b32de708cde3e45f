// AngularLattice: the scanner's (elevation, azimuth) grid of one organized
// scan (paper Sec. 4.1, Fig. 5a). It maps any point to its (row, col) in O(1)
// and a cell back to its ray direction.
//
// The lattice frame L is the scanner frame rotated so that the scanner's
// vertical rotation axis is +Z (R_scanner_lattice absorbs tilt). In L:
//   azimuth   = atan2(y, x)              [rad], one value per column
//   elevation = atan2(z, sqrt(x^2+y^2))  [rad], one value per row
// Azimuths are unwrapped along the columns (monotonic), so a full 360 degree
// scan has no seam. The inverse map uses the robust linear fit
//   col ~ (azimuth - azimuth0) / azimuth_step, row ~ (elevation - elevation0) / elevation_step
// with per-row/col tables for the exact angles.
#ifndef EDGEFIT_SCAN_ANGULAR_LATTICE_H_
#define EDGEFIT_SCAN_ANGULAR_LATTICE_H_

#include <Eigen/Core>
#include <vector>

namespace edgefit {

class AngularLattice {
 public:
  AngularLattice() = default;
  // A lattice from its per-row elevations and per-column azimuths [rad], both
  // monotonic, and the scanner tilt R_scanner_lattice.
  AngularLattice(std::vector<double> row_elevations, std::vector<double> col_azimuths,
                 const Eigen::Matrix3d& R_scanner_lattice = Eigen::Matrix3d::Identity());

  bool valid() const { return !row_elevations_.empty() && !col_azimuths_.empty(); }
  int rows() const { return static_cast<int>(row_elevations_.size()); }
  int cols() const { return static_cast<int>(col_azimuths_.size()); }

  double elevation(int row) const { return row_elevations_[row]; }
  double azimuth(int col) const { return col_azimuths_[col]; }
  // Signed mean step between adjacent rows / columns [rad].
  double elevation_step() const { return elevation_step_; }
  double azimuth_step() const { return azimuth_step_; }
  const Eigen::Matrix3d& R_scanner_lattice() const { return R_scanner_lattice_; }
  // True when the columns close the full circle (|cols * azimuth_step| ~ 2 pi):
  // then column cols-1 neighbours column 0 and projection wraps around.
  bool full_circle() const { return full_circle_; }

  // Fractional (row, col) of a point in the scanner frame; false when it falls
  // outside the grid (by more than half a step) or at the scanner origin. O(1).
  bool Project(const Eigen::Vector3d& p_scanner, double* row, double* col) const;
  // Nearest cell of a point in the scanner frame; false outside the grid. O(1).
  bool ProjectToCell(const Eigen::Vector3d& p_scanner, int* row, int* col) const;
  // Unit ray direction of cell (row, col) in the scanner frame.
  Eigen::Vector3d Direction(int row, int col) const;
  // Lattice-frame angles of a scanner-frame point [rad]; the azimuth is not
  // yet unwrapped to the column range.
  void Angles(const Eigen::Vector3d& p_scanner, double* elevation, double* azimuth) const;

 private:
  std::vector<double> row_elevations_;
  std::vector<double> col_azimuths_;
  Eigen::Matrix3d R_scanner_lattice_ = Eigen::Matrix3d::Identity();
  double elevation0_ = 0.0, elevation_step_ = 0.0;
  double azimuth0_ = 0.0, azimuth_step_ = 0.0;
  double azimuth_center_ = 0.0;  // middle of the column range [rad]
  bool full_circle_ = false;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCAN_ANGULAR_LATTICE_H_
