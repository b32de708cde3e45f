// Private: the builders behind AddAccessories, one per kind of part. Each
// returns false (and leaves *mesh empty) when it finds no valid placement.
#ifndef EDGEFIT_SRC_SCENE_ACCESSORY_PARTS_H_
#define EDGEFIT_SRC_SCENE_ACCESSORY_PARTS_H_

#include <Eigen/Core>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scene/accessories.h"
#include "edgefit/core/split_mix64.h"
#include "surface_clearance.h"

namespace edgefit {
namespace scene_internal {

struct PartContext {
  const KinematicModel* model = nullptr;
  const std::vector<Pose>* T_world_link = nullptr;
  const AccessoryOptions* options = nullptr;
  const SurfaceClearance* clearance = nullptr;
  std::vector<int> chain;  // MainChainLinks(*model)
};

// A point where a tube runs over a link, for a clamp bracket.
struct ClampSite {
  int link = -1;
  Eigen::Vector3d p_world;        // tube centre [m]
  Eigen::Vector3d tangent_world;  // unit, along the tube
  double radius = 0.0;            // tube radius [m]
};

// A harness over chain[first..last] (last > first). Fills *mesh, *radius,
// the links its control points lie on (*links) and clamp sites.
bool BuildHarness(const PartContext& context, int first, int last, SplitMix64* rng,
                  TriangleMesh* mesh, double* radius, std::vector<int>* links,
                  std::vector<ClampSite>* clamps);

// A hose from the forearm to the last chain link with a loop.
bool BuildHose(const PartContext& context, SplitMix64* rng, TriangleMesh* mesh, double* radius,
               std::vector<int>* links);

// A cover shell over one side of `link`.
bool BuildCover(const PartContext& context, int link, SplitMix64* rng, TriangleMesh* mesh);

// An L-bracket standing on the surface point nearest to `site.p_world`,
// its upright leg beside the tube.
bool BuildClampBracket(const PartContext& context, const ClampSite& site, SplitMix64* rng,
                       TriangleMesh* mesh);

// An L-bracket at a seeded surface sample of `link`.
bool BuildFreeBracket(const PartContext& context, int link, SplitMix64* rng, TriangleMesh* mesh);

// Closed L-shaped prism in the frame T_world_bracket: the plate spans
// y in [0, plate], z in [0, thickness]; the upright leg y in [0, thickness],
// z in [0, height]; both extruded over x in [-width/2, width/2].
TriangleMesh MakeLBracketMesh(const Pose& T_world_bracket, double width, double plate,
                              double height, double thickness);

// Closed slab over a height-field grid in the frame T_world_grid: corner
// (i, j), i <= nu, j <= nv, is at (x0 + i dx, y0 + j dy, bottom[i + j (nu+1)])
// on the underside and `thickness` higher on top.
TriangleMesh MakeHeightFieldSlab(const Pose& T_world_grid, double x0, double y0, double dx,
                                 double dy, int nu, int nv, const std::vector<double>& bottom,
                                 double thickness);

}  // namespace scene_internal
}  // namespace edgefit

#endif  // EDGEFIT_SRC_SCENE_ACCESSORY_PARTS_H_
