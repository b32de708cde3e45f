// Protective jackets (paint shops, foundries, welding cells): fabric covers
// over the upper arm and forearm that follow the link's surface a few
// millimetres off it. In a scan they are surfaces the CAD model lacks, close
// enough to the link that a fit takes them for it and leans outwards.
//
// A jacket over link L: L's mesh (link frame) welded and split down to
// max_edge, the triangles whose vertices all lie in a band along L's
// longest box axis covering a seeded fraction [coverage_min, coverage_max]
// of its length and which face away from that axis (a sleeve: no end faces,
// no inner faces of a fork), each vertex moved outwards along its area-weighted normal
// by an offset that varies linearly along the band between two seeded
// values in [offset_min, offset_max]. Its cells are labelled
// kLabelAccessory | kJacketFlag.
#ifndef EDGEFIT_SCENE_JACKETS_H_
#define EDGEFIT_SCENE_JACKETS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scene/scene.h"

namespace edgefit {

struct JacketOptions {
  bool enabled = false;
  // Links to cover, by name. Empty: the upper arm and the forearm, taken as
  // the two main-chain links (MainChainLinks, without its first two and
  // last two links) with the longest box side.
  std::vector<std::string> links;
  double offset_min = 0.003;    // [m] jacket surface off the link surface
  double offset_max = 0.008;    // [m]
  double coverage_min = 0.4;    // fraction of the link's length covered
  double coverage_max = 0.8;
  double max_edge = 0.03;       // [m] the link mesh is split down to this first
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// The links JacketOptions::links names, or the default upper arm and forearm.
std::vector<int> JacketLinks(const KinematicModel& model, const JacketOptions& options);

// Adds one jacket per link of JacketLinks, posed by T_world_link.
// Fails on a link name the model lacks.
Status AddJackets(const KinematicModel& model, const std::vector<Pose>& T_world_link,
                  const JacketOptions& options, Scene* scene);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_JACKETS_H_
