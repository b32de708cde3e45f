#include "edgefit/edges/region_growing.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "edgefit/core/point_kdtree.h"

namespace edgefit {
namespace {

// Neighbour lists in compressed rows, built in fixed blocks of candidates
// so that threads fill disjoint blocks.
constexpr size_t kBlock = 4096;

struct NeighbourBlock {
  std::vector<uint32_t> offsets;  // kBlock + 1 (fewer in the last block)
  std::vector<uint32_t> indices;  // sorted by index per candidate
};

std::vector<NeighbourBlock> FindNeighbours(const EdgeCandidates& candidates, float radius) {
  PointVectorAdaptor adaptor{&candidates.p_world};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const size_t n = candidates.size();
  const size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<NeighbourBlock> out(blocks);
  const float radius2 = radius * radius;  // nanoflann L2 takes squared radii
#pragma omp parallel
  {
    std::vector<std::pair<uint32_t, float>> matches;
    const nanoflann::SearchParams params(32, 0.0f, /*sorted=*/false);
#pragma omp for schedule(dynamic, 1)
    for (int64_t b = 0; b < static_cast<int64_t>(blocks); ++b) {
      NeighbourBlock& block = out[static_cast<size_t>(b)];
      const size_t begin = static_cast<size_t>(b) * kBlock;
      const size_t end = std::min(n, begin + kBlock);
      block.offsets.reserve(end - begin + 1);
      block.offsets.push_back(0);
      for (size_t i = begin; i < end; ++i) {
        matches.clear();
        tree.radiusSearch(candidates.p_world[i].data(), radius2, matches, params);
        const size_t first = block.indices.size();
        for (const auto& match : matches) {
          if (match.first != i) block.indices.push_back(match.first);
        }
        // Index order makes the growing independent of the tree's layout.
        std::sort(block.indices.begin() + static_cast<std::ptrdiff_t>(first), block.indices.end());
        block.offsets.push_back(static_cast<uint32_t>(block.indices.size()));
      }
    }
  }
  return out;
}

}  // namespace

void EdgeCandidates::Reserve(size_t n) {
  p_world.reserve(n);
  n_world.reserve(n);
  score.reserve(n);
}

void EdgeCandidates::Add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, float s) {
  p_world.push_back(p);
  n_world.push_back(n);
  score.push_back(s);
}

void GrowEdgeRegions(const EdgeCandidates& candidates, const RegionGrowingOptions& options,
                     RegionGrowingResult* result) {
  CHECK(result != nullptr);
  const size_t n = candidates.size();
  CHECK_EQ(candidates.n_world.size(), n);
  CHECK_EQ(candidates.score.size(), n);
  CHECK_LT(n, static_cast<size_t>(INT32_MAX));
  result->region.assign(n, -1);
  result->regions = 0;
  result->edge_points = 0;
  if (n == 0) return;

  const std::vector<NeighbourBlock> neighbours =
      FindNeighbours(candidates, static_cast<float>(options.radius));

  // Seeds by increasing score, ties by index (stable sort on an index order).
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return candidates.score[a] < candidates.score[b];
  });

  const float tau_region = static_cast<float>(options.tau_region);
  std::vector<uint8_t> assigned(n, 0);
  std::vector<uint32_t> members;  // breadth-first queue of the current region
  for (const uint32_t seed : order) {
    if (assigned[seed]) continue;
    members.clear();
    members.push_back(seed);
    assigned[seed] = 1;
    for (size_t head = 0; head < members.size(); ++head) {
      const uint32_t current = members[head];
      const Eigen::Vector3f& n_current = candidates.n_world[current];
      const NeighbourBlock& block = neighbours[current / kBlock];
      const size_t local = current % kBlock;
      for (uint32_t j = block.offsets[local]; j < block.offsets[local + 1]; ++j) {
        const uint32_t k = block.indices[j];
        if (assigned[k]) continue;
        if (std::abs(n_current.dot(candidates.n_world[k])) > tau_region) {  // Eq. (5)
          assigned[k] = 1;
          members.push_back(k);
        }
      }
    }
    if (members.size() < static_cast<size_t>(options.tau_min)) continue;  // noise
    const int32_t id = static_cast<int32_t>(result->regions++);
    for (const uint32_t k : members) result->region[k] = id;
    result->edge_points += members.size();
  }
}

}  // namespace edgefit
