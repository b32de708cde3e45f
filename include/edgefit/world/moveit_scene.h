// The background as MoveIt's scene text (`.scene`, what RViz's Motion
// Planning panel imports and PlanningScene::loadGeometryFromStream reads;
// the format with object poses, MoveIt 1.1 and MoveIt 2): the occupied
// voxels cut into tiles of `tile` voxels along each axis, one collision
// object per tile ("background_<i>_<j>_<k>", its tile's integer index), each
// the closed outer surface of its voxels (VoxelUnionSurface) in the world
// frame, metres. Tiles keep each object small enough for a planner's
// broad phase and each piece watertight.
#ifndef EDGEFIT_WORLD_MOVEIT_SCENE_H_
#define EDGEFIT_WORLD_MOVEIT_SCENE_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

// Writes the scene named `name` of `voxels` (OccupiedVoxels; sorted) of
// edge `voxel` [m] to `path`.
Status WriteMoveItScene(const std::vector<std::array<int32_t, 3>>& voxels, double voxel, int tile,
                        const std::string& name, const std::string& path);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_MOVEIT_SCENE_H_
