#include "solvers/registration/residual_options.h"

#include <cmath>
#include <memory>

#include "costs/robust_loss.h"

namespace edgefit {

const char* JointParameterizationName(JointParameterization parameterization) {
  switch (parameterization) {
    case JointParameterization::kJointSpace:
      return "joint_space";
    case JointParameterization::kPoseWithPenalties:
      return "pose_penalty";
  }
  return "?";
}

Status ParseJointParameterization(const std::string& name, JointParameterization* out) {
  for (const JointParameterization p :
       {JointParameterization::kJointSpace, JointParameterization::kPoseWithPenalties}) {
    if (name == JointParameterizationName(p)) {
      *out = p;
      return Status::Ok();
    }
  }
  return Status::Error("unknown joint parameterisation '" + name +
                       "' (valid: joint_space, pose_penalty)");
}

bool ResidualOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(lambda >= 0.0) || !std::isfinite(lambda)) return fail("lambda must be finite and >= 0");
  std::unique_ptr<ceres::LossFunction> loss_function;
  const Status status = MakeLoss(loss, loss_scale, &loss_function);
  if (!status.ok()) return fail(status.message());
  return true;
}

}  // namespace edgefit
