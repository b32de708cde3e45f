// The scan points of a fitted model (paper Sec. 1: the scanned equipment is
// replaced by its movable CAD model before motion planning): every valid
// point within `distance` of the posed model's surface. `edgefit fit
// --out_background` writes the scan without them.
//
// Through the scan lattice: the model's surface is sampled, each sample
// projected into each scan's grid, and the cells within `distance` of it in
// a window around its cell are marked. Scans without a lattice (unorganized
// files) are left unchanged.
#ifndef EDGEFIT_PIPELINE_MODEL_POINTS_H_
#define EDGEFIT_PIPELINE_MODEL_POINTS_H_

#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct ModelPointsOptions {
  // A point within this of the model's surface is the model's [m]: 8 mm is
  // 8 sigma of the paper's 1 mm range noise plus the fit's error.
  double distance = 0.008;
  // Surface sample spacing [m]; a point between samples is at most about
  // spacing / 2 farther from the nearest one, so it adds to `distance`.
  double sample_spacing = 0.003;
  uint64_t seed = 1;
};

// The model's surface samples at (q, T_world_base), world frame.
std::vector<Eigen::Vector3f> WorldSurfaceSamples(const KinematicModel& model,
                                                 const std::vector<double>& q,
                                                 const Pose& T_world_base, double spacing,
                                                 uint64_t seed);

// on_model[s][cell] = 1 for the points of the model at (q, T_world_base).
// Fails on q of the wrong size or bad options.
Status MarkModelPoints(const ScanSet& scans, const KinematicModel& model,
                       const std::vector<double>& q, const Pose& T_world_base,
                       const ModelPointsOptions& options,
                       std::vector<std::vector<uint8_t>>* on_model);

// Sets the marked points of *scans missing; returns how many were valid.
size_t RemoveMarkedPoints(const std::vector<std::vector<uint8_t>>& marks, ScanSet* scans);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_MODEL_POINTS_H_
