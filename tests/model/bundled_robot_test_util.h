// Shared by the solver and pipeline tests: the bundled robot with its weld
// gun attached at tool0, at a posture.
#ifndef EDGEFIT_TESTS_MODEL_BUNDLED_ROBOT_TEST_UTIL_H_
#define EDGEFIT_TESTS_MODEL_BUNDLED_ROBOT_TEST_UTIL_H_

#include <glog/logging.h>

#include <string>
#include <vector>

#include "edgefit/model/composition.h"
#include "edgefit/model/joint_values.h"
#include "edgefit/model/kinematic_model.h"

namespace edgefit {
namespace testing_util {

// Loads assets/robot/robot.urdf with weld_gun.urdf@tool0 into *model and
// sets *q to `joints` (name=value,... as `edgefit scan --joints`; the rest
// 0), the dependent joints resolved. Aborts on failure.
inline void LoadBundledRobotWithGun(const std::string& joints, KinematicModel* model,
                                    std::vector<double>* q) {
  const std::string dir = std::string(EDGEFIT_SOURCE_DIR) + "/assets/robot/";
  AttachSpec gun;
  CHECK(ParseAttachSpec(dir + "weld_gun.urdf@tool0", &gun).ok());
  CHECK(LoadModelWithAttachments(dir + "robot.urdf", {gun}, ModelLoadOptions(), model).ok());
  *q = model->ZeroJoints();
  CHECK(ParseJointAssignments(joints, *model, q).ok());
  CHECK(model->ResolveDependentJoints(q).ok());
}

}  // namespace testing_util
}  // namespace edgefit

#endif  // EDGEFIT_TESTS_MODEL_BUNDLED_ROBOT_TEST_UTIL_H_
