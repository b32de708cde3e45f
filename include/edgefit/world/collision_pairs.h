// Which pairs of one machine's links a self-collision check skips: MoveIt's
// <disable_collisions> reasons, as cell.srdf lists them.
//   "Adjacent"  the two links are joined by a joint;
//   "Always"    their meshes touch in every posture tried (the posture as
//               scanned and `samples` seeded postures within the limits):
//               parts that overlap by design, or links with no moving joint
//               between them that touch;
//   "Default"   their meshes touch in the posture as scanned but not always
//               (MoveIt's setup assistant disables these too): the machine
//               stood so when scanned, so the contact is the CAD's, not a
//               collision.
// A self-collision check takes every other pair of links with meshes that
// have a moving joint between them (SelfCheckedPairs).
#ifndef EDGEFIT_WORLD_COLLISION_PAIRS_H_
#define EDGEFIT_WORLD_COLLISION_PAIRS_H_

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

struct LinkPair {
  int link_a = -1;  // model link indices, link_a < link_b
  int link_b = -1;
  std::string reason;  // "Adjacent", "Always", "Default"
};

struct CollisionPairsOptions {
  // Postures tried for "Always": seeded uniform draws within each joint's
  // limits (continuous joints over a turn); postures whose loop closures
  // cannot be met are skipped.
  int samples = 64;
  uint64_t seed = 1;
};

// The pairs to skip, for a machine posed as scanned by q (size joints(),
// dependent joints resolved): Adjacent pairs in joint order, then the
// touching pairs in link order.
std::vector<LinkPair> DisabledCollisionPairs(const KinematicModel& model,
                                             const std::vector<double>& q_as_scanned,
                                             const CollisionPairsOptions& options);

// The links of two machines, each posed (T_world_link per link), whose
// meshes touch or cross: (link of a, link of b) in link order. cell.srdf
// disables them ("Default"): the machines stood so when scanned.
std::vector<std::pair<int, int>> TouchingLinks(const KinematicModel& a, const std::vector<Pose>& T_world_a,
                                               const KinematicModel& b, const std::vector<Pose>& T_world_b);

// Whether a moving joint lies on the tree path between the two links.
bool MoveRelative(const KinematicModel& model, int link_a, int link_b);

// An SRDF's <disable_collisions> pairs (cell.srdf) as `model`'s link
// indices, lower first; one line naming the file on unreadable XML or an
// unknown link.
Status ReadDisabledCollisionPairs(const std::string& path, const KinematicModel& model,
                                  std::set<std::pair<int, int>>* pairs);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_COLLISION_PAIRS_H_
