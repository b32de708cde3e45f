// The fitted cell as a world that motion planners load (`edgefit world`):
// every fitted machine, placed where the fit found it, in files that
// urdfdom (check_urdf, RViz, MoveIt), DART and pybullet read. Written into
// one folder, whole or not at all:
//   cell.urdf                 a root link "world"; each machine's links and
//                             joints prefixed "<name>_"; a fixed joint
//                             "world_to_<name>" at its fitted base; joints
//                             with their limits (effort and velocity as the
//                             machine's URDF gives them) and mimics; each
//                             link's mesh as meshes/<name>_<link>.stl in its
//                             link frame, referenced relative to the URDF,
//                             as its visual and its collision, and what
//                             rides on it off its CAD as a second collision;
//   cell_frozen.urdf          the same with every joint fixed at its fitted
//                             value (for consumers that cannot set joints);
//   cell.srdf                 a group per machine (its moving joints), a
//                             group_state "as_scanned" with the fitted
//                             values, and the link pairs a self-collision
//                             check skips (collision_pairs.h: "Adjacent",
//                             "Always", "Default");
//   joint_states.yaml         sensor_msgs/JointState of every machine's
//                             moving joints (prefixed names), as fitted;
//   machines_as_scanned.ply   every machine's collision meshes (attachments
//                             included) posed at the fitted values, world
//                             frame, metres;
//   background.ply, .bt       with background points (the scan less every
//                             fitted machine): its occupied voxels, less
//                             those the machines' meshes as scanned touch
//                             (CarveVoxels: no ghost of a machine stays in
//                             its own way), as a closed mesh and an OctoMap
//                             tree (background_voxels.h).
// A link's mesh is the surface edgefit fitted: its URDF's visual geometry
// (KinematicModel's Link::mesh), attachments included. Links without a mesh
// are frames.
#ifndef EDGEFIT_WORLD_PLANNING_WORLD_H_
#define EDGEFIT_WORLD_PLANNING_WORLD_H_

#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/world/background_voxels.h"

namespace edgefit {

struct WorldMachine {
  std::string name;                     // instance name: letters, digits, '_' and '-'
  const KinematicModel* model = nullptr;  // loaded with its attachments
  Pose T_world_base = Pose::Identity();   // the fitted base (root link) pose
  std::vector<double> q;                  // the fitted values, model order
  std::string source;                     // where it came from (a result.json), for messages
  // What rides on each link off its CAD (AttachedGeometry; link frame):
  // empty, or one mesh per link (empty where nothing rides). Written as
  // meshes/<name>_<link>_attached.stl, a second <collision> of the link.
  std::vector<TriangleMesh> attached;
};

// The machines' names and values as WritePlanningWorld checks them, for a
// caller to check before long work.
Status CheckWorldMachines(const std::vector<WorldMachine>& machines);

// Writes the files above into `folder`: first into a temporary folder
// beside it, which then takes its place (an existing `folder` is replaced
// only when every file was written). `background` (world frame; null: no
// background files). *written (may be null): the files, in order. Fails
// with one line (nothing written) for no machines, a name that is empty,
// repeated or not of the allowed characters, or q of the wrong size or not
// finite.
Status WritePlanningWorld(const std::vector<WorldMachine>& machines,
                          const std::vector<Eigen::Vector3f>* background,
                          const BackgroundOptions& background_options, const std::string& folder,
                          std::vector<std::string>* written);

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_PLANNING_WORLD_H_
