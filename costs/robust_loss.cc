#include "costs/robust_loss.h"

#include <glog/logging.h>

#include <cmath>

namespace edgefit {

const std::vector<std::string>& LossNames() {
  static const std::vector<std::string> kNames = {"trivial", "huber",  "cauchy",
                                                  "soft_l1", "arctan", "tukey"};
  return kNames;
}

Status MakeLoss(const std::string& name, double scale, std::unique_ptr<ceres::LossFunction>* loss) {
  CHECK(loss != nullptr);
  if (name == "trivial") {
    *loss = std::make_unique<ceres::TrivialLoss>();
    return Status::Ok();
  }
  bool known = false;
  for (const std::string& valid : LossNames()) known = known || valid == name;
  if (!known) {
    std::string valid_names;
    for (const std::string& valid : LossNames()) {
      valid_names += (valid_names.empty() ? "" : ", ") + valid;
    }
    return Status::Error("unknown loss '" + name + "' (valid: " + valid_names + ")");
  }
  if (!std::isfinite(scale) || scale <= 0.0) {
    return Status::Error("loss '" + name + "': scale must be finite and positive, got " +
                         std::to_string(scale));
  }
  if (name == "huber") {
    *loss = std::make_unique<ceres::HuberLoss>(scale);
  } else if (name == "cauchy") {
    *loss = std::make_unique<ceres::CauchyLoss>(scale);
  } else if (name == "soft_l1") {
    *loss = std::make_unique<ceres::SoftLOneLoss>(scale);
  } else if (name == "arctan") {
    *loss = std::make_unique<ceres::ArctanLoss>(scale * scale);
  } else {
    CHECK_EQ(name, "tukey");
    *loss = std::make_unique<ceres::TukeyLoss>(scale);
  }
  return Status::Ok();
}

}  // namespace edgefit
