// Joint values given by name: on the command line (--joints) or as a named
// posture in a JSON file. Values are radians / metres; on the command line a
// unit suffix may say otherwise: "joint_2=-30deg", "slide=250mm".
#ifndef EDGEFIT_MODEL_JOINT_VALUES_H_
#define EDGEFIT_MODEL_JOINT_VALUES_H_

#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/status.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {

// The name=value pairs of "name=value,name=value" (values as above), in
// order; no model checks. Fails on an item that is not name=value.
Status ParseNamedValues(const std::string& text,
                        std::vector<std::pair<std::string, double>>* values);

// Sets independent joints in *q (size joints()) from "name=value,name=value".
// Fails, naming the joint, on an unknown or dependent (mimic, loop-closure,
// fixed) joint, a malformed value, or a value outside the joint's limits.
// Joints not named keep their value in *q.
Status ParseJointAssignments(const std::string& text, const KinematicModel& model,
                             std::vector<double>* q);

// Sets the joints of posture `name` from a postures file
//   {"postures": {"<name>": {"<joint>": value, ...}, ...}}
// with the same checks as ParseJointAssignments.
Status LoadNamedPosture(const std::string& path, const std::string& name,
                        const KinematicModel& model, std::vector<double>* q);

// The posture names in a postures file, in file order.
Status ListPostures(const std::string& path, std::vector<std::string>* names);

}  // namespace edgefit

#endif  // EDGEFIT_MODEL_JOINT_VALUES_H_
