#include "edgefit/world/world_truth.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "edgefit/core/point_kdtree.h"
#include "edgefit/model/mesh_loader.h"
#include "edgefit/model/mesh_proximity.h"
#include "edgefit/world/background_voxels.h"

namespace edgefit {
namespace {

using Cell = std::array<int32_t, 3>;

// A cell as one 64-bit key (21 bits an axis: +-2^20 cells).
uint64_t Key(const Cell& c) {
  constexpr int64_t kOffset = int64_t{1} << 20;
  constexpr uint64_t kMask = (uint64_t{1} << 21) - 1;
  return (static_cast<uint64_t>(c[0] + kOffset) & kMask) << 42 |
         (static_cast<uint64_t>(c[1] + kOffset) & kMask) << 21 | (static_cast<uint64_t>(c[2] + kOffset) & kMask);
}

// Whether p lies within `reach` of the union of the cubes `cells` (edge
// `size`): inside one, or within reach of one's faces.
bool NearCubes(const std::unordered_set<uint64_t>& cells, double size, const Eigen::Vector3d& p, double reach) {
  if (cells.count(Key(VoxelOf(p, size))) > 0) return true;
  const Cell lo = VoxelOf(Eigen::Vector3d(p.array() - reach), size);
  const Cell hi = VoxelOf(Eigen::Vector3d(p.array() + reach), size);
  for (int32_t x = lo[0]; x <= hi[0]; ++x) {
    for (int32_t y = lo[1]; y <= hi[1]; ++y) {
      for (int32_t z = lo[2]; z <= hi[2]; ++z) {
        if (cells.count(Key({x, y, z})) == 0) continue;
        const Eigen::Vector3d min = Eigen::Vector3d(x, y, z) * size;
        const Eigen::Vector3d gap = (min - p).cwiseMax(p - (min.array() + size).matrix()).cwiseMax(0.0);
        if (gap.squaredNorm() <= reach * reach) return true;
      }
    }
  }
  return false;
}

double Share(size_t part, size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

Status ScoreWorldTruth(const TruthPoints& truth, const std::string& world_dir, const WorldTruthOptions& options,
                       WorldTruthScore* score) {
  *score = WorldTruthScore();
  // The background: background.bt's occupied voxels.
  std::vector<Cell> voxels;
  double voxel = 0.0;
  const double inf = std::numeric_limits<double>::infinity();
  EDGEFIT_RETURN_IF_ERROR(ReadBackgroundVoxels(
      world_dir + "/background.bt",
      Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf)), &voxels, &voxel));
  std::unordered_set<uint64_t> background;
  background.reserve(voxels.size());
  for (const Cell& v : voxels) background.insert(Key(v));
  // The machines as scanned.
  TriangleMesh machines;
  EDGEFIT_RETURN_IF_ERROR(LoadMesh(world_dir + "/machines_as_scanned.ply", Eigen::Vector3d::Ones(), &machines));
  const MeshProximity machine_grid(
      machines, std::max({options.machine_reach, options.accessory_reach, options.far_reach}), 0.05);
  // The machines' and accessories' points, and the cells of `far` within
  // which lies every point nearer than `far` to one of them.
  std::vector<Eigen::Vector3f> machine_points;
  for (size_t i = 0; i < truth.points.size(); ++i) {
    if (truth.kinds[i] != TruthKind::kBackground) machine_points.push_back(truth.points[i]);
  }
  std::unordered_set<uint64_t> near_machines;
  for (const Eigen::Vector3f& p : machine_points) {
    const Cell c = VoxelOf(p, options.far);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) near_machines.insert(Key({c[0] + dx, c[1] + dy, c[2] + dz}));
      }
    }
  }
  PointVectorAdaptor adaptor{&machine_points};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const auto far_from_machines = [&](const Eigen::Vector3f& p) {
    if (machine_points.empty() || near_machines.count(Key(VoxelOf(p, options.far))) == 0) return true;
    uint32_t index = 0;
    float d2 = 0.0f;
    nanoflann::KNNResultSet<float, uint32_t> result(1);
    result.init(&index, &d2);
    tree.findNeighbors(result, p.data(), nanoflann::SearchParams());
    return d2 > options.far * options.far;
  };

  const int64_t count = static_cast<int64_t>(truth.points.size());
  size_t n_background = 0, n_machine = 0, n_accessory = 0, n_far = 0;
  size_t covered = 0, ghosts = 0, machine_covered = 0, accessory_covered = 0, far_taken = 0;
#pragma omp parallel for schedule(dynamic, 65536) \
    reduction(+ : n_background, n_machine, n_accessory, n_far, covered, ghosts, machine_covered, accessory_covered, far_taken)
  for (int64_t i = 0; i < count; ++i) {
    const Eigen::Vector3f& q = truth.points[static_cast<size_t>(i)];
    const Eigen::Vector3d p = q.cast<double>();
    switch (truth.kinds[static_cast<size_t>(i)]) {
      case TruthKind::kBackground:
        ++n_background;
        if (NearCubes(background, voxel, p, options.background_reach)) ++covered;
        if (far_from_machines(q)) {
          ++n_far;
          if (machine_grid.Within(p, options.far_reach)) ++far_taken;
        }
        break;
      case TruthKind::kMachine:
        ++n_machine;
        if (NearCubes(background, voxel, p, options.ghost_reach)) ++ghosts;
        if (machine_grid.Within(p, options.machine_reach)) ++machine_covered;
        break;
      case TruthKind::kAccessory:
        ++n_accessory;
        if (NearCubes(background, voxel, p, options.ghost_reach)) ++ghosts;
        if (machine_grid.Within(p, options.accessory_reach)) ++accessory_covered;
        break;
    }
  }
  score->background = n_background;
  score->machine = n_machine;
  score->accessory = n_accessory;
  score->far_background = n_far;
  score->background_covered = Share(covered, n_background);
  score->machines_in_background = Share(ghosts, n_machine + n_accessory);
  score->machine_covered = Share(machine_covered, n_machine);
  score->accessory_covered = Share(accessory_covered, n_accessory);
  score->far_background_on_machines = Share(far_taken, n_far);
  return Status::Ok();
}

}  // namespace edgefit
