#include "least_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace edgefit {
namespace {

void SortByBound(std::vector<MeshPair>* pairs) {
  std::sort(pairs->begin(), pairs->end(), [](const MeshPair& x, const MeshPair& y) {
    return std::tie(x.bound, x.a, x.b) < std::tie(y.bound, y.a, y.b);
  });
}

void TakeContact(const MeshPair& p, LeastDistance* least) {
  least->contact = true;
  least->contact_a = p.a;
  least->contact_b = p.b;
  p.mesh_a->Collides(*p.T_a, *p.mesh_b, *p.T_b, &least->p_world);
}

}  // namespace

double PairCache::LowerBound(const MeshPair& pair) const {
  if (pair.cache < 0 || static_cast<size_t>(pair.cache) >= slots_.size()) return 0.0;
  const Slot& slot = slots_[static_cast<size_t>(pair.cache)];
  if (!slot.valid) return 0.0;
  // A point x of the sphere moved by |T' x - T x| <= |T' c - T c| + angle * radius.
  const Pose T_b_a = Relative(pair);
  const double angle = Eigen::AngleAxisd(T_b_a.linear() * slot.T_b_a.linear().transpose()).angle();
  const double moved = (T_b_a * pair.centre_a - slot.T_b_a * pair.centre_a).norm() + angle * pair.radius_a;
  return std::max(0.0, slot.found - moved);
}

double PairCache::Distance(const MeshPair& pair, double limit) {
  if (pair.cache < 0 || static_cast<size_t>(pair.cache) >= slots_.size()) {
    return pair.mesh_a->Distance(*pair.T_a, *pair.mesh_b, *pair.T_b, limit);
  }
  Slot& slot = slots_[static_cast<size_t>(pair.cache)];
  const Pose T_b_a = Relative(pair);
  if (slot.valid && (T_b_a.matrix() - slot.T_b_a.matrix()).cwiseAbs().maxCoeff() <= 1e-12) {
    if (slot.found < slot.limit) return std::min(slot.found, limit);  // exact
    if (limit <= slot.limit) return limit;                            // not below slot.limit
  }
  slot = {true, T_b_a, pair.mesh_a->Distance(*pair.T_a, *pair.mesh_b, *pair.T_b, limit), limit};
  return slot.found;
}

LeastDistance FindLeastDistance(std::vector<MeshPair> pairs, double start, double first_cap, PairCache* cache) {
  if (cache != nullptr) {
    for (MeshPair& p : pairs) p.bound = std::max(p.bound, cache->LowerBound(p));
  }
  SortByBound(&pairs);
  LeastDistance least;
  least.distance = start;
  constexpr double kFirstCap = 0.01, kLastCap = 1e3;  // [m]
  for (double cap = std::isfinite(first_cap) ? std::max(first_cap, 1e-9) : kFirstCap;; cap *= 4.0) {
    const bool last = cap >= least.distance || cap > kLastCap;  // seeking below the least found
    for (const MeshPair& p : pairs) {
      const double limit = last ? least.distance : std::min(least.distance, cap);
      if (p.bound >= limit) break;
      const double d = cache != nullptr ? cache->Distance(p, limit) : p.mesh_a->Distance(*p.T_a, *p.mesh_b, *p.T_b, limit);
      if (d < limit) least.distance = d;
      if (d == 0.0 && !least.contact) TakeContact(p, &least);
    }
    if (last || least.distance < cap) return least;
  }
}

LeastDistance FindContact(std::vector<MeshPair> pairs) {
  SortByBound(&pairs);
  LeastDistance least;
  least.distance = std::numeric_limits<double>::infinity();
  for (const MeshPair& p : pairs) {
    if (p.bound > 0.0) break;
    if (p.mesh_a->Collides(*p.T_a, *p.mesh_b, *p.T_b)) {
      least.distance = 0.0;
      TakeContact(p, &least);
      break;
    }
  }
  return least;
}

}  // namespace edgefit
