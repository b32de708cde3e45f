// Solids of revolution about the local z-axis: shafts, housings, flanges,
// bolt heads (6 segments give a hexagon), cone tips, tubes and rings.
// A profile is given in the (r, z) half-plane; steps in r at equal z make
// flat annular faces, so shoulders and flanges have real sharp rims.
#ifndef EDGEFIT_ASSETS_REVOLVED_MESH_H_
#define EDGEFIT_ASSETS_REVOLVED_MESH_H_

#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// One profile point: radius r >= 0 [m] at height z [m].
struct RadialSection {
  double z = 0.0;
  double r = 0.0;
};

// A solid bounded by the profile and flat caps at its first (bottom, facing
// -z) and last (top, facing +z) sections. The solid lies to the left of the
// profile walked from first to last with r to the right and z up (so a
// simple shaft goes up along its outer surface). r = 0 is allowed only at the
// first or last section (a cone tip). `segments` >= 3 around; `phase` [rad]
// rotates the first one (pi/6 with 6 segments puts a hexagon's flat on +x).
TriangleMesh MakeRevolvedSolid(const std::vector<RadialSection>& profile, int segments,
                               double phase = 0.0);

// A ring-shaped solid (tube, flange ring, bearing race): the closed profile
// polygon (>= 3 points, all r > 0) counter-clockwise in the (r, z) plane is
// swept around the z-axis. No caps; the mesh has genus one.
TriangleMesh MakeRevolvedRing(const std::vector<RadialSection>& closed_profile, int segments);

// A tube from z = 0 to `length` with inner and outer radii [m], both rims
// chamfered by `chamfer` [m] (0 for none; < (r_outer - r_inner) / 2).
TriangleMesh MakeTube(double r_inner, double r_outer, double length, double chamfer,
                      int segments);

}  // namespace edgefit

#endif  // EDGEFIT_ASSETS_REVOLVED_MESH_H_
