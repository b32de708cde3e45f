// The background's pieces that float beside a machine: what is left there
// of its points after its own and the attached ones were taken (a hose's
// few points beyond the attachment's reach, noise, mixed pixels the
// detector missed). Left in, they are the machine's ghost, in the way of its
// first motion. A piece is a 26-connected component of occupied voxels; it
// floats beside a machine when every voxel of it lies within `near` of the
// machines' collision geometry as scanned (their meshes and what rides on
// them). Real objects stand on something, the floor, a table, a fence, and
// reach beyond with it. A smaller object that rests only on a machine (a
// part on a conveyor's carriage), or hangs alone beside an arm, unscanned
// above, is taken for the machine's, as the attached points are.
#ifndef EDGEFIT_WORLD_FLOATING_VOXELS_H_
#define EDGEFIT_WORLD_FLOATING_VOXELS_H_

#include <array>
#include <cstdint>
#include <vector>

#include "edgefit/world/planning_world.h"

namespace edgefit {

// The voxels of `voxels` (sorted; edge `voxel` [m]) in pieces that float
// beside one of `machines` (posed as fitted), sorted.
std::vector<std::array<int32_t, 3>> FloatingVoxels(const std::vector<WorldMachine>& machines,
                                                   const std::vector<std::array<int32_t, 3>>& voxels,
                                                   double voxel, double near);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_FLOATING_VOXELS_H_
