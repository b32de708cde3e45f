// The least distance over pairs of posed meshes (fcl_mesh.h), exact, sought
// so that far pairs cost little: pairs by a least distance they may have
// (their bounding spheres', and their cache slot's, below), nearest first,
// in passes whose cap grows 4-fold from a
// first cap (a bound on the answer when one is known, else 1 cm). A pass
// seeks each pair's distance only below the cap, or the least found, which
// FCL prunes at once where the pair is farther; the search ends with a pass
// that finds one below its cap, or with the pass without a cap. A pair with
// a cache slot is bounded also by what the slot found, less how far mesh a
// can have moved relative to b since (a run of waypoints seldom brings a
// far pair near); one whose relative pose is the slot's takes its answer.
#ifndef EDGEFIT_WORLD_LEAST_DISTANCE_H_
#define EDGEFIT_WORLD_LEAST_DISTANCE_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "fcl_mesh.h"

namespace edgefit {

// Mesh a at T_a and mesh b at T_b (borrowed); `bound` [m]: a least
// distance they may have (their spheres'); a, b: the caller's names for
// them; `cache`: the pair's slot in a PairCache, or -1; centre_a, radius_a:
// a sphere around mesh a in its frame [m].
struct MeshPair {
  double bound = 0.0;
  int a = -1, b = -1;
  const FclMesh* mesh_a = nullptr;
  const Pose* T_a = nullptr;
  const FclMesh* mesh_b = nullptr;
  const Pose* T_b = nullptr;
  int cache = -1;
  Eigen::Vector3d centre_a = Eigen::Vector3d::Zero();
  double radius_a = 0.0;
};

// Per slot: a pair's relative pose (a seen from b) and what was found
// there: the distance when below the limit sought, else that limit; a
// bound below the distance either way.
class PairCache {
 public:
  explicit PairCache(size_t slots = 0) : slots_(slots) {}
  // A bound below the distance of `pair` now: the slot's, less how far
  // mesh a's sphere has moved relative to b since (0 without a slot).
  double LowerBound(const MeshPair& pair) const;
  // The distance of `pair` below `limit`, from the slot when the pose is
  // its own (within 1e-12), else from FCL (and kept).
  double Distance(const MeshPair& pair, double limit);

 private:
  struct Slot {
    bool valid = false;
    Pose T_b_a = Pose::Identity();
    double found = 0.0, limit = 0.0;
  };
  static Pose Relative(const MeshPair& pair) { return pair.T_b->inverse() * *pair.T_a; }
  std::vector<Slot> slots_;
};

struct LeastDistance {
  double distance = 0.0;  // [m] the least, or the start when none is nearer
  bool contact = false;   // a pair touches or crosses: the first, in sphere order
  int contact_a = -1, contact_b = -1;
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();  // where they meet
};

// The least distance over `pairs` below `start` [m], searched from
// `first_cap` [m] (infinite: from 1 cm) as the file comment says; `cache`
// may be null.
LeastDistance FindLeastDistance(std::vector<MeshPair> pairs, double start, double first_cap, PairCache* cache);

// The first pair, in sphere order, that touches or crosses (spheres apart
// are not tried); `distance` 0 when there is one, else infinite.
LeastDistance FindContact(std::vector<MeshPair> pairs);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_LEAST_DISTANCE_H_
