// A written planning world against a virtual scan's truth (`edgefit world
// --labels`): the measures of the world's bar, taken on the files as
// written, from every labelled point of the scans as read:
//   background_covered      true background points within 3 cm of
//                           background.ply (the union of background.bt's
//                           voxels, which background.ply bounds);
//   machines_in_background  machine and accessory points inside that union
//                           or within 1 cm of it: the machines' ghosts;
//   machine_covered         machine (link) points within 1 cm of
//                           machines_as_scanned.ply;
//   accessory_covered       accessory points within 3 cm of it;
//   far_background_on_machines
//                           background points farther than 10 cm from every
//                           machine and accessory point, within 1 cm of
//                           machines_as_scanned.ply: background the machines
//                           wrongly took.
// Distances are exact: to the voxels' boxes and to the mesh's triangles.
// Mixed pixels (a beam that fell on two surfaces) are no surface and count
// in no measure.
#ifndef EDGEFIT_WORLD_WORLD_TRUTH_H_
#define EDGEFIT_WORLD_WORLD_TRUTH_H_

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

enum class TruthKind : uint8_t { kBackground = 0, kMachine = 1, kAccessory = 2 };

// The labelled surface points of the scans (world frame), mixed pixels out.
struct TruthPoints {
  std::vector<Eigen::Vector3f> points;
  std::vector<TruthKind> kinds;
};

struct WorldTruthOptions {
  double background_reach = 0.03;  // [m] a background point near background.ply
  double ghost_reach = 0.01;       // [m] a machine point this near the background is its ghost
  double machine_reach = 0.01;     // [m] a machine point near machines_as_scanned.ply
  double accessory_reach = 0.03;   // [m] an accessory point near it
  double far = 0.10;               // [m] background this far from the machines' points
  double far_reach = 0.01;         // [m] and this near machines_as_scanned.ply was taken
};

struct WorldTruthScore {
  size_t background = 0, machine = 0, accessory = 0;  // points of each kind
  size_t far_background = 0;                          // background points `far` from the machines
  // Shares in [0, 1], as in the file comment.
  double background_covered = 0.0;
  double machines_in_background = 0.0;
  double machine_covered = 0.0;
  double accessory_covered = 0.0;
  double far_background_on_machines = 0.0;
};

// Scores the world written in `world_dir` (background.bt,
// machines_as_scanned.ply) against `truth`.
Status ScoreWorldTruth(const TruthPoints& truth, const std::string& world_dir,
                       const WorldTruthOptions& options, WorldTruthScore* score);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_WORLD_TRUTH_H_
