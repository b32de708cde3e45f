// The background of a planning world: the scans less every fitted machine,
// less its ghost, and what rides on each machine off its CAD given to it.
//   1. each machine's points (MarkModelPoints, within its removal distance)
//      and the points attached to them (MarkAttachedPoints: dress packs,
//      hoses, covers) leave the scans; the attached ones become collision
//      geometry of the link they ride on (AttachedGeometry,
//      WorldMachine::attached);
//   2. mixed pixels (a beam that fell on two surfaces) leave them: they
//      float between surfaces, at a machine's silhouette its ghost
//      (FindMixedPixels, and MarkSilhouetteMixedPixels at each machine's
//      silhouette); they ride on nothing;
//   3. pieces of voxels that float beside a machine on nothing else leave
//      them (FloatingVoxels): what is left there of the machine.
// The voxels within carve_margin of a machine as scanned leave the
// background later, when it is written (WritePlanningWorld).
#ifndef EDGEFIT_WORLD_WORLD_BACKGROUND_H_
#define EDGEFIT_WORLD_WORLD_BACKGROUND_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/pipeline/attached_points.h"
#include "edgefit/scan/mixed_pixels.h"
#include "edgefit/scan/organized_scan.h"
#include "edgefit/world/planning_world.h"

namespace edgefit {

struct WorldBackgroundOptions {
  double voxel = 0.02;             // [m] the attachments' and the pieces' voxels
  bool drop_mixed_pixels = true;
  MixedPixelOptions mixed_pixels;
  // Mixed pixels at a machine's silhouette are sought this many cells from
  // it: the beam's footprint spans 2-3 cells at 1.7 mm.
  int silhouette_cells = 3;
  double floating = 0.3;           // [m] a floating piece lies wholly within this; 0: none leaves
  AttachedPointsOptions attached;
};

struct WorldBackgroundSummary {
  size_t machine_points = 0;           // the machines' and their attached points
  std::vector<size_t> riding;          // per machine: its attached points
  size_t mixed_pixels = 0;  // those at the machines' silhouettes included
  size_t floating_voxels = 0, floating_points = 0;
};

// Takes every machine's points out of *scans (missing cells after), fills
// each machine's `attached` meshes, and gives the background's points
// (world frame). `removal`: each machine's removal distance [m].
Status WorldBackground(const std::vector<double>& removal, const WorldBackgroundOptions& options,
                       ScanSet* scans, std::vector<WorldMachine>* machines,
                       std::vector<Eigen::Vector3f>* background, WorldBackgroundSummary* summary);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_WORLD_BACKGROUND_H_
