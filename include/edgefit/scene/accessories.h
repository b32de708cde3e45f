// Non-modelled accessories on posed equipment (paper Sec. 1, 4, 7.1, 7.3 and
// Fig. 15b/d): real robots carry wire harnesses, hoses, covers and brackets
// that the CAD model lacks; in a scan they are outliers the edge-weighted
// fit must resist. The virtual benchmark adds them to the scene:
//
//  - harnesses: tubes (radius 10-25 mm) along the outside of the main-chain
//    links (MainChainLinks), crossing each joint with a sagging span
//    (parabolic droop, 5-15 % of the span), held by clamp brackets;
//  - hoses: thinner tubes (6-12 mm) from the forearm to the last link with
//    a loose loop near the wrist;
//  - covers: closed shells 2-4 mm thick draped 5-20 mm over one side of the
//    base and of large links (a height field of the link surface seen from
//    that side, so they occlude the CAD surface behind them);
//  - brackets: L-angles (legs 50-150 mm) on the link surface, oriented by the
//    local surface normal.
//
// Everything is derived from the posed link geometry: dense surface samples
// give, along each link, the outermost surface on the chosen side, and every
// tube point is pushed out to (radius + clearance) from the link surfaces and
// covers, so accessories sit on or just off the CAD surface and change it
// only by occluding it. Deterministic for a seed (SplitMix64 streams).
#ifndef EDGEFIT_SCENE_ACCESSORIES_H_
#define EDGEFIT_SCENE_ACCESSORIES_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/scene/scene.h"

namespace edgefit {

struct AccessoryOptions {
  // Harnesses along the main chain (0 disables). The first runs from the
  // base to the link before the wrist, the others over seeded sub-ranges of
  // at least two links.
  int harness_count = 2;
  double harness_radius_min = 0.010;  // [m]
  double harness_radius_max = 0.025;  // [m]
  double sag_fraction_min = 0.05;     // droop / span across a joint
  double sag_fraction_max = 0.15;
  double sag_max = 0.15;  // [m] cap on the droop of long spans
  // A clamp bracket under a harness on every second station of each link.
  bool harness_clamps = true;

  int hose_count = 1;              // Forearm-to-wrist hoses (0 disables).
  double hose_radius_min = 0.006;  // [m]
  double hose_radius_max = 0.012;  // [m]
  double hose_loop_min = 0.12;     // [m] how far the loop bulges out
  double hose_loop_max = 0.25;     // [m]

  // Covers: the first on the root link (if it has a mesh), the others on
  // the largest main-chain links. Each covers a seeded patch of 50-85 % x
  // 50-85 % of one side of the link's box (30-50 % when larger patches
  // would cut a neighbouring link).
  int cover_count = 2;
  double cover_thickness_min = 0.002;  // [m]
  double cover_thickness_max = 0.004;  // [m]
  double cover_offset_min = 0.005;     // [m] gap above the link surface
  double cover_offset_max = 0.020;     // [m]
  // [m] Longest side of a cover patch: a long rail gets a cover over part
  // of it, not a sheet over all of it.
  double cover_max_side = 1.2;

  int bracket_count = 4;         // Free brackets, besides harness clamps.
  double bracket_size_min = 0.05;  // [m] leg length and width
  double bracket_size_max = 0.15;  // [m]

  // [m] Gap kept between a tube's surface and link surfaces or covers.
  double clearance = 0.003;
  // [m] Finest spacing of the link surface samples (at most 8000 per link).
  double sample_spacing = 0.01;
  int tube_segments = 16;  // Vertices around a tube (>= 3).
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// One accessory as added to the scene.
struct AccessoryRecord {
  std::string kind;        // "harness", "hose", "cover", "bracket"
  int scene_index = -1;    // index into Scene::meshes
  double radius = 0.0;     // [m] tube radius (harness, hose), else 0
  std::vector<int> links;  // links it is attached to, in chain order
  double area = 0.0;       // [m^2] outward area (a cover's top sheet only)
};

struct AccessoryReport {
  int harnesses = 0;
  int hoses = 0;
  int covers = 0;
  int brackets = 0;
  double area = 0.0;  // [m^2] sum of the records' outward areas
  std::vector<AccessoryRecord> records;

  // One line, e.g. "2 harnesses, 1 hose, 2 covers, 9 brackets, 1.23 m^2".
  std::string BriefReport() const;
};

// Appends accessories (label kLabelAccessory, link -1, kind as in
// AccessoryRecord) for the model posed at q with link poses T_world_link
// (ForwardKinematics(q, ...), indexed like model.links()). Parts that find
// no place (a cover whose patch would cut another link, a bracket on a
// concave spot) are tried again elsewhere a bounded number of times, then
// left out: the report counts what was added. `report` may be null.
void AddAccessories(const KinematicModel& model, const std::vector<double>& q,
                    const std::vector<Pose>& T_world_link, const AccessoryOptions& options,
                    Scene* scene, AccessoryReport* report = nullptr);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_ACCESSORIES_H_
