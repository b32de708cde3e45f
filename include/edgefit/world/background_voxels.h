// The background of a planning world (the scan less every fitted machine)
// as collision geometry: the points' occupied voxels of one size, written as
//   background.ply  the outer faces of the voxels' union: closed pieces
//                   (every edge shared by two faces, or four where voxels
//                   meet along an edge) that hold every background point
//                   inside, world frame, metres;
//   background.bt   an OctoMap occupancy tree (liboctomap) at the same
//                   resolution, each voxel marked occupied at its centre
//                   (endpoints only, no ray casting: free space is not
//                   marked, unknown stays unknown).
// The voxels are OctoMap's own at this resolution (cell k spans
// [k v, (k + 1) v) along each axis), so both files hold the same cells.
#ifndef EDGEFIT_WORLD_BACKGROUND_VOXELS_H_
#define EDGEFIT_WORLD_BACKGROUND_VOXELS_H_

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct BackgroundOptions {
  // The voxels' edge [m]: a background point lies inside the mesh, at most
  // this far (times sqrt 3) from the surface it stands for.
  double voxel = 0.02;
};

// The occupied voxels (integer cells, sorted, unique) of world points.
std::vector<std::array<int32_t, 3>> OccupiedVoxels(const std::vector<Eigen::Vector3f>& points,
                                                   double voxel);

// The outer faces of the union of `voxels` (OccupiedVoxels) as triangles,
// normals outward.
TriangleMesh VoxelUnionSurface(const std::vector<std::array<int32_t, 3>>& voxels, double voxel);

// Writes background.ply and background.bt into `folder` (an existing folder);
// appends their names to *names.
Status WriteBackground(const std::vector<Eigen::Vector3f>& points, const BackgroundOptions& options,
                       const std::string& folder, std::vector<std::string>* names);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_BACKGROUND_VOXELS_H_
