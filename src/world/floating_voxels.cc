#include "edgefit/world/floating_voxels.h"

#include <algorithm>
#include <numeric>

#include "edgefit/core/point_kdtree.h"
#include "edgefit/model/surface_sampler.h"

namespace edgefit {
namespace {

using Voxel = std::array<int32_t, 3>;

constexpr double kSampleSpacing = 0.01;  // [m] the machines' surface samples

int Find(std::vector<int>* parent, int i) {
  while ((*parent)[static_cast<size_t>(i)] != i) {
    (*parent)[static_cast<size_t>(i)] = (*parent)[static_cast<size_t>((*parent)[static_cast<size_t>(i)])];
    i = (*parent)[static_cast<size_t>(i)];
  }
  return i;
}

}  // namespace

std::vector<Voxel> FloatingVoxels(const std::vector<WorldMachine>& machines, const std::vector<Voxel>& voxels,
                                  double voxel, double near) {
  // The machines' collision surfaces as scanned, sampled.
  std::vector<Eigen::Vector3f> surface;
  for (const WorldMachine& m : machines) {
    const std::vector<Pose> T = m.model->ForwardKinematics(m.q, m.T_world_base);
    for (size_t l = 0; l < m.model->links().size(); ++l) {
      for (const TriangleMesh* mesh : {&m.model->links()[l].mesh, m.attached.empty() ? nullptr : &m.attached[l]}) {
        if (mesh == nullptr || mesh->empty()) continue;
        for (const Eigen::Vector3f& p : SampleMeshSurface(*mesh, kSampleSpacing, l).points) {
          surface.push_back((T[l] * p.cast<double>()).cast<float>());
        }
      }
    }
  }
  if (surface.empty() || voxels.empty()) return {};
  PointVectorAdaptor adaptor{&surface};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  // A voxel is near when its centre is: the samples' spacing and the half
  // diagonal added.
  const float reach = static_cast<float>(near + kSampleSpacing + 0.87 * voxel);
  const auto is_near = [&](const Voxel& v) {
    const Eigen::Vector3f centre(static_cast<float>((v[0] + 0.5) * voxel), static_cast<float>((v[1] + 0.5) * voxel),
                                 static_cast<float>((v[2] + 0.5) * voxel));
    uint32_t index = 0;
    float d2 = 0.0f;
    nanoflann::KNNResultSet<float, uint32_t> result(1);
    result.init(&index, &d2);
    tree.findNeighbors(result, centre.data(), nanoflann::SearchParams());
    return d2 <= reach * reach;
  };
  // 26-connected pieces (union-find over the sorted voxels).
  const int count = static_cast<int>(voxels.size());
  std::vector<int> parent(voxels.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < count; ++i) {
    const Voxel& v = voxels[static_cast<size_t>(i)];
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const Voxel n = {v[0] + dx, v[1] + dy, v[2] + dz};
          if (!(v < n)) continue;  // each pair once
          const auto it = std::lower_bound(voxels.begin(), voxels.end(), n);
          if (it == voxels.end() || *it != n) continue;
          const int a = Find(&parent, i), b = Find(&parent, static_cast<int>(it - voxels.begin()));
          if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
        }
      }
    }
  }
  // A piece floats when none of its voxels is far from the machines.
  std::vector<uint8_t> grounded(voxels.size(), 0);
  for (int i = 0; i < count; ++i) {
    if (!is_near(voxels[static_cast<size_t>(i)])) grounded[static_cast<size_t>(Find(&parent, i))] = 1;
  }
  std::vector<Voxel> floating;
  for (int i = 0; i < count; ++i) {
    if (!grounded[static_cast<size_t>(Find(&parent, i))]) floating.push_back(voxels[static_cast<size_t>(i)]);
  }
  return floating;
}

}  // namespace edgefit
