// How far one machine of a planning world (planning_world.h) stays from
// everything else, posture by posture along a trajectory (`edgefit
// clearance`). The world is read back from its folder as a planner loads it:
// cell.urdf at joint_states.yaml's values, cell.srdf's disabled pairs and
// background.ply. Link meshes and the background's voxel surface (its faces
// merged into rectangles) are FCL hierarchies (fcl_mesh.h); distances are
// between surfaces, exact, in metres, and 0 when two surfaces touch or
// cross. The waypoints are measured on every thread, each a run of them.
//
// For each posture:
//   distance_to_background  the machine's links that move relative to its
//                           base, to background.ply. The base and what is
//                           fixed to it are left out: they stand on the floor
//                           or table they were scanned on, and do not move.
//   distance_to_machines    each of its links to each link of the other
//                           machines, which stay as scanned.
//   self_distance           between its links that move relative to one
//                           another, less the pairs cell.srdf disables
//                           (collision_pairs.h).
//   colliding               one of the three is 0 at the waypoint, or at a
//                           state on the way from the previous waypoint: the
//                           way is a straight line in joint space, checked at
//                           states at most ClearanceOptions' steps apart.
// The background is background.bt's occupied cells (background.ply's faces
// are theirs) where the machine's moving links go, grown by max_distance; a distance
// beyond max_distance is reported as max_distance. The cells hold every
// scanned point inside, so a distance to them errs short of the distance to
// the scanned surface by at most a voxel's diagonal (background_voxels.h).
#ifndef EDGEFIT_WORLD_CLEARANCE_H_
#define EDGEFIT_WORLD_CLEARANCE_H_

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/report/world_report.h"

namespace edgefit {

struct ClearanceOptions {
  // The way between two waypoints is checked at states where no revolute or
  // continuous joint moves more than step_rad [rad] and no prismatic joint
  // more than step_m [m] from the last state checked.
  double step_rad = 0.5 * M_PI / 180.0;
  double step_m = 0.005;
  // [m] Distances to the background are measured up to this; the background
  // farther than this from anywhere the machine reaches is not loaded.
  double max_distance = 1.0;

  bool IsValid(std::string* error) const;
};

struct PostureClearance {
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  double distance_to_background = kNone;  // [m], at most max_distance; kNone: no background
  double distance_to_machines = kNone;    // [m]; kNone: no other machine
  double self_distance = kNone;           // [m]; kNone: no pair is checked
  bool colliding = false;
  // Where the first collision is on the way from the previous waypoint, as
  // a fraction of the way (1: at this waypoint; the first waypoint: 1).
  double collision_fraction = 0.0;
  // The colliding pair: cell.urdf link names, or "background".
  std::string collision_a, collision_b;
  Eigen::Vector3d p_world_collision = Eigen::Vector3d::Zero();  // a point where they meet [m]
};

// One line on a collision: the pair, where, and how far along the way from
// the previous waypoint ("" when c is not colliding).
std::string DescribeCollision(const PostureClearance& c);

// What the picture of a check shows (ClearanceWorld::Picture).
struct ClearancePictureOptions {
  // [m] The background within this of where the machine's moving links go.
  double margin = 0.5;
  // The background's surface at most this many triangles: its voxels are
  // merged 2x2x2 until it fits (a page of 10-20 MB that stays fluid).
  size_t max_background_triangles = 400000;

  bool IsValid(std::string* error) const;
};

class ClearanceWorld {
 public:
  ClearanceWorld();
  ~ClearanceWorld();

  // Reads the world in `folder` and takes machine `machine` (an instance
  // name: the links prefixed "<machine>_" under joint "world_to_<machine>";
  // empty: the world's only machine). One line naming the file on a missing
  // or unreadable file, and the machines there are for an unknown machine
  // or, with none named, several.
  // Distances to the background beyond `max_distance` [m]
  // (ClearanceOptions::max_distance) are reported as max_distance.
  Status Load(const std::string& folder, const std::string& machine, double max_distance);

  // The machines of the world, in cell.urdf's order, and the one checked.
  const std::vector<std::string>& machines() const;
  const std::string& machine() const;
  // The cell's joint values (cell.urdf's order) with the machine's named
  // joints (its independent joints, by the names of its own URDF, without
  // the prefix) at `values` [rad] or [m] and every other joint as scanned,
  // dependent joints resolved. One line on an unknown or dependent joint, a
  // value not finite or outside the joint's limits, or a loop closure that
  // cannot be met.
  Status Posture(const std::vector<std::pair<std::string, double>>& values,
                 std::vector<double>* q_cell) const;

  // One entry per waypoint (cell joint values from Posture), in order.
  // *status: one line when background.bt cannot be read.
  std::vector<PostureClearance> Check(const std::vector<std::vector<double>>& waypoints,
                                      const ClearanceOptions& options, Status* status) const;

  // The check as a picture (report/world_report.h): the background's
  // surface near the way, every machine's links with their attachments
  // as scanned, the machine checked at each waypoint, each waypoint's
  // distances and collision (`results`, Check's for `waypoints`), and the
  // clearance along the waypoints as a plot. One line when background.bt
  // cannot be read or results do not match the waypoints.
  Status Picture(const std::vector<std::vector<double>>& waypoints,
                 const std::vector<PostureClearance>& results, const ClearancePictureOptions& options,
                 WorldReport* report) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_CLEARANCE_H_
