#include "edgefit/world/attached_geometry.h"

#include "edgefit/core/point_kdtree.h"
#include "edgefit/core/split_mix64.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/world/background_voxels.h"

namespace edgefit {

std::vector<TriangleMesh> AttachedGeometry(const KinematicModel& model, const std::vector<double>& q,
                                           const Pose& T_world_base,
                                           const std::vector<Eigen::Vector3f>& points_world,
                                           const AttachedGeometryOptions& options) {
  const std::vector<Link>& links = model.links();
  std::vector<TriangleMesh> meshes(links.size());
  if (points_world.empty()) return meshes;
  const std::vector<Pose> T_world_link = model.ForwardKinematics(q, T_world_base);
  // Every link's surface samples, posed, and whose they are.
  std::vector<Eigen::Vector3f> samples;
  std::vector<int> owner;
  for (size_t l = 0; l < links.size(); ++l) {
    if (links[l].mesh.empty()) continue;
    const SurfaceSamples s =
        SampleMeshSurface(links[l].mesh, options.sample_spacing, SplitMix64::StreamSeed(options.seed, l));
    for (const Eigen::Vector3f& p : s.points) {
      samples.push_back((T_world_link[l] * p.cast<double>()).cast<float>());
      owner.push_back(static_cast<int>(l));
    }
  }
  if (samples.empty()) return meshes;
  PointVectorAdaptor adaptor{&samples};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<std::vector<Eigen::Vector3f>> riding(links.size());  // link frame
  for (const Eigen::Vector3f& p : points_world) {
    uint32_t index = 0;
    float d2 = 0.0f;
    nanoflann::KNNResultSet<float, uint32_t> result(1);
    result.init(&index, &d2);
    tree.findNeighbors(result, p.data(), nanoflann::SearchParams());
    const size_t l = static_cast<size_t>(owner[index]);
    riding[l].push_back((T_world_link[l].inverse() * p.cast<double>()).cast<float>());
  }
  for (size_t l = 0; l < links.size(); ++l) {
    if (riding[l].empty()) continue;
    meshes[l] = VoxelUnionSurface(OccupiedVoxels(riding[l], options.voxel), options.voxel);
  }
  return meshes;
}

}  // namespace edgefit
