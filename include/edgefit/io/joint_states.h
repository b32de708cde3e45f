// Joint values from a ROS sensor_msgs/JointState YAML file (`name: [...]`,
// `position: [...]`, as `edgefit fit --out_joint_states` writes it and
// `ros2 topic echo --once /joint_states` prints it), parsed with yaml-cpp.
#ifndef EDGEFIT_IO_JOINT_STATES_H_
#define EDGEFIT_IO_JOINT_STATES_H_

#include <string>
#include <utility>
#include <vector>

#include "edgefit/core/status.h"

namespace edgefit {

// The named positions of `path` [rad] or [m], in the file's order (the
// model's KnownJoints, frozen_joints.h). Fails
// with one line naming the file when it is missing or malformed, or when
// name and position differ in length or a position is not finite.
Status ReadJointStates(const std::string& path,
                       std::vector<std::pair<std::string, double>>* values);

// The text ReadJointStates reads: `# <comment>` lines (one per line of
// `comment`), then name and position lists ("%.9g") and empty velocity and
// effort lists.
std::string JointStatesYaml(const std::vector<std::pair<std::string, double>>& values,
                            const std::string& comment);

}  // namespace edgefit

#endif  // EDGEFIT_IO_JOINT_STATES_H_
