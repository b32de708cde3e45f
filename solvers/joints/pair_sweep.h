// Extension to Sec. 5.2.1: a round body and the bend below it swept
// together. A body symmetric about its joint's axis (a roll joint's round
// link: the LBR's axes 1, 3, 5 and 7, a forearm roll) has its angle fixed
// only by where the next joint bends its children. Sec. 5.2.1 sweeps it
// with the children at their current values; before they are fitted they
// stand straight, and when that sweep is flat (every value costs about the
// same, ChainOptions::flat_sweep_loss) the roll is a guess that the bend
// then has to fit around. The pair sweep scores the body and the child's
// body on a grid over both joints' ranges, coarse to fine: the roll comes
// from the bend it holds.
#ifndef EDGEFIT_SOLVERS_JOINTS_PAIR_SWEEP_H_
#define EDGEFIT_SOLVERS_JOINTS_PAIR_SWEEP_H_

#include <limits>
#include <vector>

#include "edgefit/core/pose.h"
#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"
#include "solvers/joints/body.h"
#include "solvers/joints/joint_sweep.h"

namespace edgefit {

struct PairSweepSummary {
  double q = 0.0;                                         // the round body's joint [rad]
  double q_child = 0.0;                                   // the bend's [rad]
  double loss = std::numeric_limits<double>::infinity();  // Eq. (9), both bodies, finest grid
  int evaluations = 0;
  double seconds = 0.0;
};

// The first independent revolute joint below one of `links` (the round
// body's) whose axis is not parallel to `joint`'s (more than 30 degrees
// apart at the joints' values in q): the bend that fixes the roll. -1 when
// there is none.
int BendBelow(const KinematicModel& model, int joint, const std::vector<int>& links,
              const std::vector<double>& q);

// Sweeps `body` (on its joint, body.joint) and the body of `bend` below it
// (revolute) together over their ranges (a continuous joint: one turn) at
// `step` [rad] (on a quarter of the samples), then twice around the best at
// a fifth of the step, at the
// base pose T_world_base with the other joints at q. link_samples: every
// link's sweep samples (model order, link frames), each body's thinned to
// max_samples. Each grid point is a serial sum, scored in parallel: the
// same result for any thread count.
Status SweepPair(const KinematicModel& model, const JointSweep& sweep,
                 const JointSweepOptions& options, const Pose& T_world_base,
                 const std::vector<double>& q, const Body& body, int bend,
                 const std::vector<SurfaceSamples>& link_samples, int max_samples, double step,
                 PairSweepSummary* summary);

}  // namespace edgefit

#endif  // EDGEFIT_SOLVERS_JOINTS_PAIR_SWEEP_H_
