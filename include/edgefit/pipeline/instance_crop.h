// Cropping the scans to one instance's region (the cost of each fit in a
// cell then scales with its machine, not with the cell): after the rough
// base poses, only the cells whose rays pass within the model's reach of a
// rough base pose are kept, so that what the fit may see, what may hide it
// (occluders in front) and what lies behind it stay as they were, and the
// rest of the cell leaves the fit's stages.
#ifndef EDGEFIT_PIPELINE_INSTANCE_CROP_H_
#define EDGEFIT_PIPELINE_INSTANCE_CROP_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "edgefit/model/kinematic_model.h"
#include "edgefit/scan/organized_scan.h"

namespace edgefit {

struct InstanceCropOptions {
  // Off for one asset (edgefit fit: its scan is its window already); the
  // cell fit (cell_fit.h) turns it on for every fit.
  bool enabled = false;
  // Added to the model's reach: the rough base pose's error and the
  // scanner's range noise [m].
  double margin = 0.3;

  bool IsValid(std::string* error) const;
};

// An upper bound on the distance from the root link's origin to any surface
// of `model` at any joint values within limits [m]: along the chain the
// joints' origin offsets, the prismatic travels, and each link's mesh radius.
double ModelReach(const KinematicModel& model);

// `scans` with every cell missing whose ray from its scanner passes farther
// than `radius` from all `centers_world`. Scanners within `radius` of a
// center keep every cell.
ScanSet CropToRays(const ScanSet& scans, const std::vector<Eigen::Vector3d>& centers_world,
                   double radius);

// `scans` with every point outside `box_world` missing (edgefit fit --roi).
ScanSet CropToBox(const ScanSet& scans, const Eigen::AlignedBox3d& box_world);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_INSTANCE_CROP_H_
