// What rides on a machine off its CAD (dress packs, hoses, covers, an
// unmodelled tool: the points MarkAttachedPoints finds) as collision
// geometry of the links it rides on, so that the arm in the planning world
// is as thick as on the line. Each point goes to the link whose surface is
// nearest as scanned; each link's points, in its own frame, become the
// outer faces of their occupied voxels (VoxelUnionSurface): closed, every
// point inside, moving with the link.
#ifndef EDGEFIT_WORLD_ATTACHED_GEOMETRY_H_
#define EDGEFIT_WORLD_ATTACHED_GEOMETRY_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

struct AttachedGeometryOptions {
  double voxel = 0.02;            // [m] the voxels' edge, in each link's frame
  double sample_spacing = 0.01;   // [m] link surface samples for the nearest link
  uint64_t seed = 1;
};

// One mesh per link of `model` (link frame; empty where nothing rides),
// for the machine posed by q (dependent joints resolved) at T_world_base
// and the attached points (world frame).
std::vector<TriangleMesh> AttachedGeometry(const KinematicModel& model, const std::vector<double>& q,
                                           const Pose& T_world_base,
                                           const std::vector<Eigen::Vector3f>& points_world,
                                           const AttachedGeometryOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_ATTACHED_GEOMETRY_H_
