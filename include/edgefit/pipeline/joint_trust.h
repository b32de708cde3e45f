// Joints whose own bodies fit, not trusted for their neighbours' sake:
// rules over a fit's verdicts (FitResult::bodies, parents first), applied
// after each body has been judged alone (src/pipeline/quality.cc). A joint
// they touch becomes ambiguous and says why.
#ifndef EDGEFIT_PIPELINE_JOINT_TRUST_H_
#define EDGEFIT_PIPELINE_JOINT_TRUST_H_

#include "edgefit/model/kinematic_model.h"
#include "edgefit/pipeline/fit_result.h"

namespace edgefit {

// No joint is ok below a body that does not match (the base's included):
// a joint's value is the turn between two links, and a link the scan does
// not confirm may be anywhere (on a depth frame, the base on a round pillar
// with a wrist that fits the pillar too). Sets chain_unmatched.
void DistrustBelowUnmatched(const KinematicModel& model, FitResult* result);

// On a noisy scan (noise_scale > 1) a round joint (symmetric: its sweep
// and ICP carried its children) and its partner, the first joint below its
// body, were fitted together: neither is ok when the other has two values
// that fit about as well. On a virtual depth frame of the Med7 its wrist
// flipped (A5 142 degrees off, the flip fitting as well) took the elbow A4
// 5.7 degrees off with a standard deviation of 0.8 degrees; on one of the
// bundled robot at 4.1 m, A4 half a turn off and ambiguous left A5 ok and
// 38.8 degrees off (its mirror value: the wrist's flip). Laser scans
// (noise_scale 1) are left as they were. Sets partner_torn.
void DistrustTornPairs(const KinematicModel& model, FitResult* result);

}  // namespace edgefit

#endif  // EDGEFIT_PIPELINE_JOINT_TRUST_H_
