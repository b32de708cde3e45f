// Known joints: a model with some joints held at given values, as fixed
// joints (their motion at the value folded into their origin), so that a
// fit of it fits the others only; with every joint known the model is one
// rigid body and the fit finds the base alone (camera-to-robot calibration).
// The mimic joints of a held joint are held with it. Joint indices do not
// change, so a FitResult of the frozen model reads against the original.
#ifndef EDGEFIT_MODEL_FROZEN_JOINTS_H_
#define EDGEFIT_MODEL_FROZEN_JOINTS_H_

#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// Joint values by name [rad] or [m].
using KnownJoints = std::vector<std::pair<std::string, double>>;

// *frozen: `model` with the `known` independent joints (and their mimic
// joints) fixed at their values. Fails, naming the joint, on an unknown,
// fixed or dependent joint (give the joint it follows), a value outside the
// joint's limits, or a joint named twice.
Status FreezeJoints(const KinematicModel& model, const KnownJoints& known,
                    KinematicModel* frozen);

// The original model's joint values from a fit of the frozen one: the
// known joints (and their mimic joints) set to their values in *q.
void SetKnownJoints(const KinematicModel& model, const KnownJoints& known,
                    std::vector<double>* q);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_FROZEN_JOINTS_H_
