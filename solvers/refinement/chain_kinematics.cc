#include "solvers/refinement/chain_kinematics.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgefit {

namespace {
constexpr double kStep = 1e-6;  // central difference step [rad] or [m]
}  // namespace

ChainKinematics::ChainKinematics(const KinematicModel* model, const Pose& T_world_base_anchor,
                                 const std::vector<double>& q_full, const double* delta_base,
                                 const double* q)
    : model_(model),
      T_world_base_anchor_(T_world_base_anchor),
      delta_base_(delta_base),
      q_(q),
      q_full_(q_full),
      independent_(model->IndependentJoints()) {
  CHECK_EQ(q_full.size(), model->joints().size());
  CHECK(delta_base != nullptr && (q != nullptr || independent_.empty()));
  const size_t parameters = 6 + independent_.size();
  key_.assign(parameters, std::numeric_limits<double>::quiet_NaN());
  links_.resize(model->links().size());
  for (LinkPoseJacobian& link : links_) {
    link.dR.resize(parameters);
    link.dt.resize(parameters);
  }
}

Pose ChainKinematics::BasePose(const double* delta_base) const {
  const Eigen::Vector3d rotation(delta_base[0], delta_base[1], delta_base[2]);
  const double angle = rotation.norm();
  const Eigen::Matrix3d R_delta =
      angle > 0.0 ? Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix()
                  : Eigen::Matrix3d::Identity();
  Pose T = Pose::Identity();
  T.linear() = R_delta * T_world_base_anchor_.linear();
  T.translation() = T_world_base_anchor_.translation() +
                    Eigen::Vector3d(delta_base[3], delta_base[4], delta_base[5]);
  return T;
}

std::vector<double> ChainKinematics::FullJoints(const double* q) {
  for (size_t k = 0; k < independent_.size(); ++k) {
    q_full_[static_cast<size_t>(independent_[k])] = q[k];
  }
  // A closure that cannot be met keeps its best values: the residuals then
  // see the mechanism as far as it goes, as the sequential fit does.
  (void)model_->ResolveDependentJoints(&q_full_);
  return q_full_;
}

std::vector<Pose> ChainKinematics::Links(const double* delta_base, const double* q) {
  return model_->ForwardKinematics(FullJoints(q), BasePose(delta_base));
}

void ChainKinematics::PrepareForEvaluation(bool /*evaluate_jacobians*/,
                                           bool /*new_evaluation_point*/) {
  // The derivatives are computed with the poses at every new point (the
  // warm starts of the loop closures then follow the same sequence of
  // points whatever Ceres asks for); a point already held is kept.
  const double* delta_base = delta_base_;
  const double* q = q_;
  const size_t n = independent_.size();
  if (std::equal(delta_base, delta_base + 6, key_.begin()) &&
      (n == 0 || std::equal(q, q + n, key_.begin() + 6))) {
    return;
  }
  std::vector<double> x(6 + n);
  std::copy(delta_base, delta_base + 6, x.begin());
  if (n > 0) std::copy(q, q + n, x.begin() + 6);
  key_ = x;
  const std::vector<double> q_warm = q_full_;
  const std::vector<Pose> T = Links(x.data(), x.data() + 6);
  for (size_t l = 0; l < links_.size(); ++l) {
    links_[l].R = T[l].linear();
    links_[l].t = T[l].translation();
  }
  std::vector<double> x_step = x;
  for (size_t k = 0; k < x.size(); ++k) {
    x_step[k] = x[k] + kStep;
    q_full_ = q_warm;
    const std::vector<Pose> T_plus = Links(x_step.data(), x_step.data() + 6);
    x_step[k] = x[k] - kStep;
    q_full_ = q_warm;
    const std::vector<Pose> T_minus = Links(x_step.data(), x_step.data() + 6);
    x_step[k] = x[k];
    for (size_t l = 0; l < links_.size(); ++l) {
      links_[l].dR[k] = (T_plus[l].linear() - T_minus[l].linear()) / (2.0 * kStep);
      links_[l].dt[k] = (T_plus[l].translation() - T_minus[l].translation()) / (2.0 * kStep);
    }
  }
  q_full_ = q_warm;
  FullJoints(x.data() + 6);  // leave the warm start at x
}

const LinkPoseJacobian& ChainKinematics::At(int link) const {
  CHECK(!std::isnan(key_.front())) << "ChainKinematics::At before PrepareForEvaluation";
  return links_[static_cast<size_t>(link)];
}

}  // namespace edgefit
