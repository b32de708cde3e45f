// Extension: which joints the geometry itself can pin. A revolute joint
// whose whole subtree (its link and everything it carries, at the fitted
// values of the joints below) looks the same turned about the joint's axis,
// like a bare round flange, cannot be told by any scan; and a revolute
// joint whose range exceeds a full turn reaches the same geometry at values
// 2 pi apart (a cable wind-up no scan shows).
#ifndef EDGEFIT_SOLVERS_JOINTS_OBSERVABILITY_H_
#define EDGEFIT_SOLVERS_JOINTS_OBSERVABILITY_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"

namespace edgefit {

struct ObservabilityOptions {
  // The subtree is turned about the axis by each of these angles [rad]; a
  // sample is moved off the CAD surface when its nearest unturned sample is
  // more than surface_tolerance from it along that sample's normal, or more
  // than gap_spacings sample spacings away (turned into a hole or beside
  // the part). Unobservable when no turn moves more than max_off_share of
  // the samples off: what is left is relief a scan does not reliably read.
  // Measured at 4 mm samples, the largest share over the turns: bare
  // flanges (bolt holes, a faceted rim) of the FANUC M-900iB 0.014, KUKA
  // KR 150 0.10, ABB IRB 6700 0.13, the bundled robot 0.03; the bundled
  // robot's forearm 0.42 (two-fold round: 0.09 at the half turn); wrists
  // (joint 5) 0.54-0.85; a flange carrying the bundled gun 0.74 (the
  // X16005 on a KUKA 0.75, at 12 mm samples). At 1 mm the flanges'
  // facets and holes move 10-28 % off and a bare KUKA flange fitted 31 deg
  // off passed the scan's pinning test: the holes do not pin it.
  std::vector<double> turns = {0.05, 0.2, 0.5, 1.0, 2.0, 3.14159};
  double surface_tolerance = 0.004;  // [m]
  double gap_spacings = 1.5;
  double max_off_share = 0.25;
  // The subtree's samples are thinned evenly to at most this many (an arm's
  // subtree has 100 k and more at 4 mm; the test needs its shape, not all).
  int max_samples = 20000;

  bool IsValid(std::string* error) const;
};

// The share of `samples` (a subtree's, in the frame of the joint's child
// link, where the axis passes through the origin along axis_child) that
// the turn by `angle` about the axis moves off the unturned surface.
// spacing: the samples' spacing [m].
double TurnedOffShare(const SurfaceSamples& samples, const Eigen::Vector3d& axis_child,
                      double angle, double spacing, const ObservabilityOptions& options);

// Whether no scan can pin revolute joint `joint` at values q: its subtree
// (link_samples: every link's, link frame, at `spacing`) is moved off its
// own surface by none of options.turns. False for prismatic or fixed joints
// and for an empty subtree. *largest_off_share (may be null): the largest
// share a turn moved off; the test stops at the first turn over
// max_off_share, so for a joint it pins that turn's share.
bool TurnIsUnobservable(const KinematicModel& model, int joint, const std::vector<double>& q,
                        const std::vector<SurfaceSamples>& link_samples, double spacing,
                        const ObservabilityOptions& options, double* largest_off_share = nullptr);

// The base's own symmetry. When the root link's first revolute joint turns
// about an axis through the base, the base's yaw about that axis and the
// joint trade off exactly: turned by t with the joint at q - t, every link
// below is where it was. A base that looks the same turned by t (a square
// plate every quarter turn: the bundled robot's and the balancer arm's at
// most 5 % of their samples move off; the KUKA's, ABB's and FANUC's 38 % and
// more at every turn) leaves the split to no scan.
struct BaseSymmetry {
  int joint = -1;             // the root's first revolute joint; -1: none
  std::vector<double> turns;  // turns in (0, 2 pi) the base looks the same at [rad]
  // Round: the base looks the same at every turn tested, 10 and 20 degrees
  // too (a cobot's round base): no scan tells its yaw from the joint's
  // value at all, and the joint is reported at zero (unobservable).
  bool round = false;
};

// The symmetry of the base body (the root link and the links fixed to it;
// link_samples: every link's, link frame, at `spacing`), tested at every
// multiple of 30 and 45 degrees, and at 10 and 20 degrees for `round`.
BaseSymmetry FindBaseSymmetry(const KinematicModel& model,
                              const std::vector<SurfaceSamples>& link_samples, double spacing,
                              const ObservabilityOptions& options);

// T_world_base with the base turned so that `joint` can read q_new instead
// of q_old and every link below stays where it was.
Pose TurnBaseForJoint(const KinematicModel& model, int joint, const Pose& T_world_base,
                      double q_old, double q_new);

// The values of revolute joint j within its limits that place every link
// as q_j does: q_j + 2 pi k, ascending (q_j itself included; a joint with
// a range of at most a full turn or without limits gives just q_j).
std::vector<double> WholeTurns(const Joint& j, double q_j);

// The value a joint no scan can pin is reported at: its zero, or the limit
// nearest it.
double ZeroOrNearestLimit(const Joint& j);

// The reporting convention among WholeTurns: the value nearest the joint's
// zero (q_j itself on a tie); a continuous joint's value in [-pi, pi].
double NearestZeroTurn(const Joint& j, double q_j);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_JOINTS_OBSERVABILITY_H_
