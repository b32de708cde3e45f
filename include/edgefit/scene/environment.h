// Surroundings of the equipment in a virtual factory scan (paper Sec. 7.3,
// Fig. 16): a floor and a few clutter objects (pillars, pallets with boxes,
// fence panels). They are labelled background: a fit must ignore them, and
// those between a scanner and the asset occlude it as in a real cell.
//
// Placement: every clutter object stands on the floor with a seeded yaw, at a
// seeded position whose world-axis-aligned footprint (x-y) lies outside the
// asset box grown by `keep_out_margin` and inside the box grown by
// `clutter_max_distance`: the ring a scanner 2.5-5 m from the asset sees.
// Objects do not overlap one another. Deterministic for a seed (SplitMix64).
#ifndef EDGEFIT_SCENE_ENVIRONMENT_H_
#define EDGEFIT_SCENE_ENVIRONMENT_H_

#include <Eigen/Geometry>
#include <cstdint>
#include <string>

#include "edgefit/scene/scene.h"

namespace edgefit {

struct EnvironmentOptions {
  bool add_floor = true;
  // [m] The floor is a closed slab whose top face is the plane z = floor_z,
  // so rays from above hit its top.
  double floor_z = 0.0;
  // [m] Half the floor's edge length, centred under the asset; grown if
  // needed to carry every clutter object.
  double floor_half_extent = 15.0;
  double floor_thickness = 0.2;  // [m]
  int clutter_count = 4;         // Pillars, pallets, fence panels (cycled, seeded order).
  // [m] Clearance between the asset box (x-y) and any clutter footprint.
  double keep_out_margin = 0.5;
  // [m] Clutter footprints stay within the asset box grown by this (x-y).
  double clutter_max_distance = 4.0;
  uint64_t seed = 1;

  bool IsValid(std::string* error) const;
};

// Appends the floor ("floor") and clutter ("pillar", "pallet", "fence"),
// all kLabelBackground, around `asset_box_world` (the posed asset's box; an
// empty box is taken as the origin). Clutter that finds no free spot in a
// bounded number of seeded tries is left out (logged), never forced in.
void AddEnvironment(const Eigen::AlignedBox3d& asset_box_world, const EnvironmentOptions& options,
                    Scene* scene);

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_ENVIRONMENT_H_
