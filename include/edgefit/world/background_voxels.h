// The background of a planning world (the scan less every fitted machine)
// as collision geometry: the points' occupied voxels of one size, written as
//   background.ply  the outer faces of the voxels' union: closed pieces
//                   (every edge shared by two faces, or four where voxels
//                   meet along an edge) that hold every background point
//                   inside, world frame, metres;
//   background.scene  MoveIt's scene text of the same voxels, in tiles
//                   (moveit_scene.h);
//   background.bt   an OctoMap occupancy tree (liboctomap) at the same
//                   resolution, each voxel marked occupied at its centre
//                   (endpoints only, no ray casting: free space is not
//                   marked, unknown stays unknown).
// The voxels are OctoMap's own at this resolution (cell k spans
// [k v, (k + 1) v) along each axis), so both files hold the same cells.
#ifndef EDGEFIT_WORLD_BACKGROUND_VOXELS_H_
#define EDGEFIT_WORLD_BACKGROUND_VOXELS_H_

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct BackgroundOptions {
  // The voxels' edge [m]: a background point lies inside the mesh, at most
  // this far (times sqrt 3) from the surface it stands for.
  double voxel = 0.02;
  // [m] The voxels within this of a machine as scanned are taken as free
  // (CarveVoxels): what is left there of the machine's own points would
  // block its first motion.
  double carve_margin = 0.02;
  // background.scene's tiles, in voxels along each axis (moveit_scene.h):
  // 100 voxels of 20 mm, 2 m.
  int scene_tile = 100;
};

// The voxel (integer cell) that holds world point p.
template <typename Point>
std::array<int32_t, 3> VoxelOf(const Point& p, double voxel) {
  return {static_cast<int32_t>(std::floor(p.x() / voxel)), static_cast<int32_t>(std::floor(p.y() / voxel)),
          static_cast<int32_t>(std::floor(p.z() / voxel))};
}

// The occupied voxels (integer cells, sorted, unique) of world points.
std::vector<std::array<int32_t, 3>> OccupiedVoxels(const std::vector<Eigen::Vector3f>& points,
                                                   double voxel);

// The outer faces of the union of `voxels` (OccupiedVoxels) as triangles,
// normals outward.
TriangleMesh VoxelUnionSurface(const std::vector<std::array<int32_t, 3>>& voxels, double voxel);

// The same surface with each plane's neighbouring faces merged into
// rectangles (rows, then rows of equal extent): far fewer triangles (a
// floor's thousands of faces become a few), for collision and distance
// queries; not a closed mesh (a rectangle's corner may lie on another's
// edge), so not for files that promise one.
TriangleMesh VoxelUnionRectangles(const std::vector<std::array<int32_t, 3>>& voxels, double voxel);

// Removes from *voxels (sorted) the cells whose cube, grown by `margin`
// [m] on every side, touches the surface of `mesh_world` (world frame):
// space a machine filled when it was scanned, and its rim, where what is
// left of its points (mixed pixels, noise beyond the removal distance)
// would be its own ghost. Returns how many were removed.
size_t CarveVoxels(const TriangleMesh& mesh_world, double voxel, double margin,
                   std::vector<std::array<int32_t, 3>>* voxels);

// Writes background.ply, background.scene and background.bt of `voxels` (OccupiedVoxels, less
// what was carved) into `folder` (an existing folder); appends their names
// to *names.
Status WriteBackground(const std::vector<std::array<int32_t, 3>>& voxels,
                       const BackgroundOptions& options, const std::string& folder,
                       std::vector<std::string>* names);

// The occupied cells of a background.bt that lie in `region` (world frame),
// sorted, and the tree's voxel [m].
Status ReadBackgroundVoxels(const std::string& path, const Eigen::AlignedBox3d& region,
                            std::vector<std::array<int32_t, 3>>* voxels, double* voxel);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_BACKGROUND_VOXELS_H_
