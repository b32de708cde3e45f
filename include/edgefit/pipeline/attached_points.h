// The points attached to a fitted instance that its CAD model does not hold:
// dress packs, hoses, covers, jackets. They move with the machine, so they
// leave the background with it, and they must not be taken for another
// machine's parts by the next search of a cell (cell_fit.h): a conveyor's
// rough stage took a removed robot's left-over harnesses for its tips.
//
// Grown on each scan's grid from the instance's own points (MarkModelPoints):
// a 4-neighbour joins when it lies within max_gap of the point it is reached
// from, within max_distance of the fitted model's surface and min_height
// above its base (the floor it stands on does not join).
#ifndef EDGEFIT_PIPELINE_ATTACHED_POINTS_H_
#define EDGEFIT_PIPELINE_ATTACHED_POINTS_H_

#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct AttachedPointsOptions {
  // Neighbouring points closer than this are one surface [m]: several point
  // spacings at grazing incidence, well below the gap between two machines.
  double max_gap = 0.015;
  // How far an attached part may stand off the model's surface [m]: the
  // accessories' hose loops bulge up to 0.25 m.
  double max_distance = 0.3;
  // Points lower than this above the base's origin stay (the floor) [m].
  double min_height = 0.03;
  // Model surface samples for the distance to it [m].
  double sample_spacing = 0.01;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// Marks (sets to 1) in `marks` the points attached to the marked ones.
Status MarkAttachedPoints(const ScanSet& scans, const KinematicModel& model,
                          const std::vector<double>& q, const Pose& T_world_base,
                          const AttachedPointsOptions& options,
                          std::vector<std::vector<uint8_t>>* marks);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_ATTACHED_POINTS_H_
