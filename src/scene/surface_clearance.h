// Private: how far a point is outside the posed link surfaces (and other
// obstacles such as covers), from dense oriented surface samples, and
// pushing points out to a wanted clearance. Accessories use it to sit on or
// just off the CAD surface without cutting into it.
#ifndef EDGEFIT_SRC_SCENE_SURFACE_CLEARANCE_H_
#define EDGEFIT_SRC_SCENE_SURFACE_CLEARANCE_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {
namespace scene_internal {

// Oriented samples of one surface in the world frame.
struct SurfaceCloud {
  int link = -1;  // link index, -1 for an obstacle that is not a link
  Eigen::AlignedBox3d box_world;
  std::vector<Eigen::Vector3d> p_world;
  std::vector<Eigen::Vector3d> n_world;  // unit, outward
  double area = 0.0;                     // [m^2] of the sampled mesh
};

class SurfaceClearance {
 public:
  // Samples every link mesh posed by T_world_link with about
  // max(min_spacing, sqrt(area / max_samples)) spacing [m].
  SurfaceClearance(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                   double min_spacing, int max_samples, uint64_t seed);

  // Adds a world-frame mesh (e.g. a cover) as an obstacle.
  void AddObstacle(const TriangleMesh& mesh_world, uint64_t seed);

  // Signed clearance [m] of p_world: over surfaces whose box grown by
  // `reach` [m] holds p, the smallest (p - s) . n_s with s the nearest
  // sample of that surface (the tangent-plane distance; negative inside).
  // +infinity when no surface is within reach. *normal gets n_s.
  double Clearance(const Eigen::Vector3d& p_world, double reach, Eigen::Vector3d* normal) const;

  // Moves p_world along the offending sample normals until its clearance is
  // at least `wanted` [m] (a few rounds, as leaving one surface can enter a
  // neighbour). Returns the moved point.
  Eigen::Vector3d PushOut(const Eigen::Vector3d& p_world, double wanted) const;

  // The cloud of link k (empty cloud for a link without a mesh).
  const SurfaceCloud& LinkCloud(int link) const { return clouds_[link]; }

 private:
  std::vector<SurfaceCloud> clouds_;  // links first (indexed by link), then obstacles
  double min_spacing_;
  int max_samples_;
};

}  // namespace scene_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_SCENE_SURFACE_CLEARANCE_H_
