// Internal: CAD-like meshes of the spot-welding robot's links and of its
// welding gun, in their link frames (see robot_layout.h).
#ifndef EDGEFIT_SRC_ASSETS_ROBOT_LINK_MESHES_H_
#define EDGEFIT_SRC_ASSETS_ROBOT_LINK_MESHES_H_

#include <vector>

#include "asset_output.h"
#include "edgefit/model/triangle_mesh.h"

namespace edgefit {
namespace assets_internal {

// A solid cylinder along +z from 0 to `length`, both rims chamfered.
TriangleMesh ChamferedCylinder(double radius, double length, double chamfer, int segments);
// A hexagon bolt head along +z from 0 to `height`, top rim chamfered.
TriangleMesh HexBoltHead(double across_corners_radius, double height);

// base_link, link_1 .. link_6, balancer_cylinder, balancer_piston.
std::vector<LinkMesh> RobotLinkMeshes();
// gun_base, gun_fixed_arm, gun_electrode (weld_gun_meshes.cc).
std::vector<LinkMesh> WeldGunLinkMeshes();

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_ROBOT_LINK_MESHES_H_
