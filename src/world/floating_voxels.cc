#include "edgefit/world/floating_voxels.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <utility>

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
  std::vector<Eigen::AlignedBox3f> boxes;  // each machine's samples'
  for (const WorldMachine& m : machines) {
    const size_t first = surface.size();
    const std::vector<Pose> T = m.model->ForwardKinematics(m.q, m.T_world_base);
    for (size_t l = 0; l < m.model->links().size(); ++l) {
      for (const TriangleMesh* mesh : {&m.model->links()[l].mesh, m.attached.empty() ? nullptr : &m.attached[l]}) {
        if (mesh == nullptr || mesh->empty()) continue;
        for (const Eigen::Vector3f& p : SampleMeshSurface(*mesh, kSampleSpacing, l).points) {
          surface.push_back((T[l] * p.cast<double>()).cast<float>());
        }
      }
    }
    boxes.emplace_back();
    for (size_t i = first; i < surface.size(); ++i) boxes.back().extend(surface[i]);
  }
  if (surface.empty() || voxels.empty()) return {};
  PointVectorAdaptor adaptor{&surface};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  // A voxel is near when its centre is: the samples' spacing and the half
  // diagonal added. Beyond the machines' boxes grown by that, none is.
  const float reach = static_cast<float>(near + kSampleSpacing + 0.87 * voxel);
  for (Eigen::AlignedBox3f& box : boxes) {
    box.min().array() -= reach;
    box.max().array() += reach;
  }
  const auto centre = [voxel](const Voxel& v) {
    return Eigen::Vector3f(static_cast<float>((v[0] + 0.5) * voxel), static_cast<float>((v[1] + 0.5) * voxel),
                           static_cast<float>((v[2] + 0.5) * voxel));
  };
  const int count = static_cast<int>(voxels.size());
  std::vector<uint8_t> is_near(voxels.size(), 0);
#pragma omp parallel for schedule(dynamic, 4096)
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3f c = centre(voxels[static_cast<size_t>(i)]);
    if (std::none_of(boxes.begin(), boxes.end(), [&](const Eigen::AlignedBox3f& box) { return box.contains(c); })) {
      continue;
    }
    uint32_t index = 0;
    float d2 = 0.0f;
    nanoflann::KNNResultSet<float, uint32_t> result(1);
    result.init(&index, &d2);
    tree.findNeighbors(result, c.data(), nanoflann::SearchParams());
    is_near[static_cast<size_t>(i)] = d2 <= reach * reach;
  }
  // 26-connected pieces (union-find over the sorted voxels): each voxel's
  // neighbours lie in the 9 columns (x, y) around its own, found by hash.
  std::unordered_map<uint64_t, std::pair<int, int>> columns;  // (x, y) -> [begin, end)
  const auto column_key = [](int32_t x, int32_t y) {
    return static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32 | static_cast<uint32_t>(y);
  };
  for (int i = 0; i < count;) {
    int end = i + 1;
    const Voxel& v = voxels[static_cast<size_t>(i)];
    while (end < count && voxels[static_cast<size_t>(end)][0] == v[0] && voxels[static_cast<size_t>(end)][1] == v[1]) {
      ++end;
    }
    columns.emplace(column_key(v[0], v[1]), std::make_pair(i, end));
    i = end;
  }
  std::vector<int> parent(voxels.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < count; ++i) {
    const Voxel& v = voxels[static_cast<size_t>(i)];
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto column = columns.find(column_key(v[0] + dx, v[1] + dy));
        if (column == columns.end()) continue;
        const auto begin = voxels.begin() + column->second.first, end = voxels.begin() + column->second.second;
        for (auto it = std::lower_bound(begin, end, Voxel{v[0] + dx, v[1] + dy, v[2] - 1});
             it != end && (*it)[2] <= v[2] + 1; ++it) {
          const int a = Find(&parent, i), b = Find(&parent, static_cast<int>(it - voxels.begin()));
          if (a != b) parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
        }
      }
    }
  }
  // A piece floats when none of its voxels is far from the machines.
  std::vector<uint8_t> grounded(voxels.size(), 0);
  for (int i = 0; i < count; ++i) {
    if (!is_near[static_cast<size_t>(i)]) grounded[static_cast<size_t>(Find(&parent, i))] = 1;
  }
  std::vector<Voxel> floating;
  for (int i = 0; i < count; ++i) {
    if (!grounded[static_cast<size_t>(Find(&parent, i))]) floating.push_back(voxels[static_cast<size_t>(i)]);
  }
  return floating;
}

}  // namespace edgefit
