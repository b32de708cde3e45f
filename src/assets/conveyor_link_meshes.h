// Internal: CAD-like meshes of the conveyance system's links in their link
// frames (conveyor_layout.h).
#ifndef EDGEFIT_SRC_ASSETS_CONVEYOR_LINK_MESHES_H_
#define EDGEFIT_SRC_ASSETS_CONVEYOR_LINK_MESHES_H_

#include <vector>

#include "asset_output.h"

namespace edgefit {
namespace assets_internal {

// base_link, carriage_1, lifter_1, carriage_2, lifter_2, clamp_2_left,
// clamp_2_right.
std::vector<LinkMesh> ConveyorLinkMeshes();

}  // namespace assets_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_ASSETS_CONVEYOR_LINK_MESHES_H_
