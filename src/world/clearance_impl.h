// ClearanceWorld's state (clearance.h): the world as loaded, shared by the
// check (clearance.cc) and its picture (clearance_report.cc).
#ifndef EDGEFIT_WORLD_CLEARANCE_IMPL_H_
#define EDGEFIT_WORLD_CLEARANCE_IMPL_H_

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "edgefit/model/kinematic_model.h"
#include "edgefit/world/clearance.h"
#include "fcl_mesh.h"
#include "least_distance.h"

namespace edgefit {

struct ClearanceWorld::Impl {
  KinematicModel cell;
  std::vector<double> q_scanned;
  std::vector<std::string> machines;
  std::string machine;                         // the one checked
  std::string prefix;                          // "<machine>_"
  std::vector<std::unique_ptr<FclMesh>> meshes;  // per cell link; null without a mesh
  std::string background_path;                 // background.bt; empty: none
  struct Sphere {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // link frame [m]
    double radius = 0.0;                               // [m], around the link's mesh
  };
  std::vector<Sphere> spheres;                 // per cell link
  double max_distance = 0.0;                   // [m] the background's distances are capped at
  std::vector<int> moving;                     // machine links with meshes that move off its base
  std::vector<int> own;                        // machine links with meshes
  // Pairs (own link, other machine's link as scanned) that cell.srdf does
  // not disable.
  std::vector<std::tuple<int, int, Pose>> others;
  std::vector<std::pair<int, int>> self_pairs;
  std::map<std::string, int> joints;           // own joint name -> cell joint (independent)
  std::vector<std::string> joint_names;

  // A cache slot per pair: moving link and background, own and other
  // machine's link, self pair.
  size_t PairSlots() const { return moving.size() + others.size() + self_pairs.size(); }
  const std::string& LinkName(int l) const { return cell.links()[static_cast<size_t>(l)].name; }
  // The last posture measured in a run of waypoints (Check): its links'
  // poses and distances, which bound where the next posture's searches
  // start, and what each pair's search found, a bound on the pair at the
  // next posture (least_distance.h).
  struct Previous {
    std::vector<Pose> T;
    PostureClearance clearance;
    PairCache pairs;  // PairSlots() slots
  };
  // Distances at one posture; with `first_only`, stops at the first contact.
  // `previous` (may be null; not with first_only): read, then set to this
  // posture.
  PostureClearance Measure(const std::vector<double>& q, bool first_only, const FclMesh* background,
                           Previous* previous = nullptr) const;
  // The box the moving links' spheres sweep over the states.
  Eigen::AlignedBox3d Reach(const std::vector<std::vector<double>>& states) const;
};

}  // namespace edgefit

#endif  // EDGEFIT_WORLD_CLEARANCE_IMPL_H_
