// The scan's floor height, which the rough base stages stand the base on
// (paper Sec. 5.1.1: the base stands level on the floor; Sec. 6.1 likewise).
//
// The floor is the most populated 5 mm height bin of the scan points whose
// surface is level, refined to the mean height of the points in it and the
// two bins on either side (the noise spreads the floor). A point's surface
// is judged from its lattice neighbours about `normal_radius` away along the
// row and the column: the cross product of the two central differences,
// without a PCA, on every `stride`-th row and column. That is all the floor
// needs, so a fit without edge weights computes no per-point normals.
#ifndef EDGEFIT_SOLVERS_BASE_FLOOR_HEIGHT_H_
#define EDGEFIT_SOLVERS_BASE_FLOOR_HEIGHT_H_

#include <Eigen/Geometry>
#include <string>

#include "edgefit/core/status.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct FloorOptions {
  // A level surface: |n_world . z| at least this (0.97: within 14 degrees).
  double normal_cos = 0.97;
  // Half the baseline of the central differences [m]; at 1 mm range noise
  // the error propagation puts a 10 mm one's floor normals within about
  // 4 degrees (estimated, not measured), well inside normal_cos.
  double normal_radius = 0.01;
  int max_half_window = 8;  // [pixels] cap for very near points
  int stride = 2;           // every stride-th row and column is tested

  bool IsValid(std::string* error) const;
};

// The floor height [m, world z] of the organized scans, inside roi_world
// when it is not empty: of the level points below the station that saw
// them (a ceiling, seen from below, is not a floor), the 2.5 cm window
// holding the most, and the mean height within 1.25 cm of its fullest 5 mm
// bin. Fails when no level surface is found (no organized scan, or no
// floor in view). Sequential and deterministic.
Status EstimateFloorHeight(const ScanSet& scans, const Eigen::AlignedBox3d& roi_world,
                           const FloorOptions& options, double* floor_z);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_FLOOR_HEIGHT_H_
