// Scene: the triangle geometry the virtual TLS scanner sees (paper Sec. 7.3):
// the posed equipment, its non-modelled accessories, a floor and clutter.
// Each mesh carries the label that scan cells hitting it receive.
#ifndef EDGEFIT_SCENE_SCENE_H_
#define EDGEFIT_SCENE_SCENE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "edgefit/model/triangle_mesh.h"

namespace edgefit {

// Per-cell labels of a virtual scan (the --labels sidecar, one uint16 per cell):
//   0 missing (no return), 1 background (floor, clutter), 2 accessory,
//   3 + k link k of the KinematicModel (links() order);
// kTrueEdgeFlag is or-ed in when the hit lies within the true-edge distance
// (1.5 mm) of a sharp mesh edge (dihedral >= 30 degrees) of the link it hit;
// kMixedPixelFlag when the beam's footprint fell on surfaces at different
// depths and the range is a mix of them (beam_footprint.h); kJacketFlag on
// accessory cells of a protective jacket (jackets.h).
constexpr uint16_t kLabelMissing = 0;
constexpr uint16_t kLabelBackground = 1;
constexpr uint16_t kLabelAccessory = 2;
constexpr uint16_t kLabelFirstLink = 3;
constexpr uint16_t kTrueEdgeFlag = 0x8000;
constexpr uint16_t kMixedPixelFlag = 0x4000;
constexpr uint16_t kJacketFlag = 0x2000;
constexpr uint16_t kLabelMask = 0x1fff;

inline uint16_t LinkLabel(int link) { return static_cast<uint16_t>(kLabelFirstLink + link); }
inline bool IsLinkLabel(uint16_t label) { return (label & kLabelMask) >= kLabelFirstLink; }
inline int LinkOfLabel(uint16_t label) { return (label & kLabelMask) - kLabelFirstLink; }

struct SceneMesh {
  TriangleMesh mesh_world;  // in the world frame [m]
  uint16_t label = kLabelBackground;
  int link = -1;            // link index for link meshes, else -1
  std::string kind;         // "link", "floor", "pillar", "box", "fence", "harness", "cover", ...
  // Diffuse reflectance in (0, 1]: scales the return's energy in a realistic
  // scan (range noise, dropouts, the mix of a mixed pixel); ideal scans ignore it.
  double reflectance = 0.5;
};

struct Scene {
  std::vector<SceneMesh> meshes;
};

}  // namespace edgefit

#endif  // EDGEFIT_SCENE_SCENE_H_
