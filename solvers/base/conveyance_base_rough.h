// Rough registration of a conveyance system's base link (paper Sec. 6.1,
// Fig. 11): the arms reaching up to hold the parts end in tips that are the
// highest points around them.
//   1. The scan's floor (given: floor_height.h); the base stands
//      level on it, so its pose is (x, y, yaw).
//   2. Scan tips: the height map of the points above the floor and its
//      convex tips (height_map.h, Eq. 11-13). Extension: each cell's height
//      corroborated by its other points (mixed pixels are no tips), and
//      only tips at a height some CAD pair of step 4 can take.
//   3. The centre axis: RANSAC over pairs of tips (symmetry_axis.h); tips
//      without a symmetric partner are dropped.
//   4. CAD tips: the same height map and tips on the model's surface samples
//      and mesh vertices at the zero posture ("vertices with large z"), and
//      the same axis; each CAD pair's width, tip heights and midpoint are
//      taken over the corners of its joints' ranges (the arms move).
//   5. Pairs matched between CAD and scan by width and height; the axis and
//      the pair midpoints align the base across the axis and in yaw (both
//      ways round). The pairs of every parallel axis take part: clamps
//      opened unequally shift their pair's axis sideways.
// Extension: the tips sit on moving links (carriages), so along the axis a
// matched pair fixes the base only to within its joints' travel. The base
// position along the axis is searched over the stretch that most matched
// pairs allow, scored by the caller's loss of the base alone at each pose
// (the Eq. 9 loss of the base's CAD samples, given by Fit); the best poses
// are the candidates, within a few cm for the precise ICP.
#ifndef EDGEFIT_SOLVERS_BASE_CONVEYANCE_BASE_ROUGH_H_
#define EDGEFIT_SOLVERS_BASE_CONVEYANCE_BASE_ROUGH_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/triangle_mesh.h"
#include "edgefit/scan/organized_scan.h"
#include "solvers/base/height_map.h"
#include "solvers/base/symmetry_axis.h"

namespace edgefit {

struct ConveyanceBaseRoughOptions {
  double cell = 0.01;  // [m] height-map cell (scan and CAD)
  ConvexTipOptions tips;
  CellSupport scan_support;  // of the scan's cell heights (not the CAD's)
  // Scan points at least this far above the floor enter the height map [m].
  double min_tip_height = 0.1;
  SymmetryAxisOptions symmetry;
  // CAD surface samples for the CAD height map [m] (with the mesh vertices).
  double model_spacing = 0.004;
  // A scan pair matches a CAD pair when its width and its tips' heights
  // are within the CAD pair's ranges widened by this [m].
  double match_tolerance = 0.03;
  // The search along the axis: a coarse step, then around the best poses
  // a fine one [m].
  double along_step = 0.03;
  double fine_step = 0.01;
  int candidates = 4;  // the best poses returned (distinct by > along_step)
  // Optional region of the scan (world frame); empty: the whole scan.
  Eigen::AlignedBox3d roi_world;

  bool IsValid(std::string* error) const;
};

struct ConveyanceBaseRoughResult {
  Pose T_world_base = Pose::Identity();  // the best candidate
  std::vector<Pose> candidates;          // best first
  double floor_z = 0.0;                  // [m]
  int convex_scan_tips = 0;              // the scan height map's
  // Of those, the ones at the CAD pairs' heights (world frame, highest first).
  std::vector<Eigen::Vector3d> scan_tips;
  std::vector<Eigen::Vector3d> model_tips;  // base frame, zero posture
  int symmetric_scan_tips = 0;              // paired about the best scan axis
  int matches = 0;                          // scan pair / CAD pair matches over all axes
  int scored = 0;                           // poses scored with the loss
  double loss = 0.0;                        // of the best
  double seconds = 0.0;
};

// Loss of the base alone at a pose (lower is better).
using BasePoseLoss = std::function<double(const Pose& T_world_base)>;

// base_mesh_link: the base body's mesh in the base frame (its lowest point
// stands on the floor); floor_z: the scan's floor height [m, world]
// (EstimateFloorHeight). Fails with a message when no symmetric tips (scan
// or CAD) or no match is found.
Status FitConveyanceBaseRough(const ScanSet& scans, double floor_z, const KinematicModel& model,
                              const TriangleMesh& base_mesh_link,
                              const ConveyanceBaseRoughOptions& options, const BasePoseLoss& loss,
                              ConveyanceBaseRoughResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_BASE_CONVEYANCE_BASE_ROUGH_H_
