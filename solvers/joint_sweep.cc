#include "solvers/joint_sweep.h"

#include <glog/logging.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "costs/sweep_loss.h"

namespace edgefit {

bool JointSweepOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(revolute_step > 0.0) || !(prismatic_step > 0.0)) return fail("sweep steps must be > 0");
  if (refinements < 0) return fail("refinements must be >= 0");
  if (!(tau_dist > 0.0)) return fail("tau_dist must be > 0");
  if (!(max_distance >= tau_dist)) return fail("max_distance must be >= tau_dist");
  if (!(occluded_loss >= 0.0)) return fail("occluded_loss must be >= 0");
  if (!(visibility_tolerance >= 0.0)) return fail("visibility_tolerance must be >= 0");
  if (lattice_window < 0) return fail("lattice_window must be >= 0");
  return true;
}

JointSweep::JointSweep(CorrespondenceSearch* search, const ScanVisibility* visibility)
    : search_(search), visibility_(visibility) {
  CHECK(search_ != nullptr && visibility_ != nullptr);
}

double JointSweep::LossAt(const SurfaceSamples& samples, const Pose& T_world_link,
                          const JointSweepOptions& options) {
  const Eigen::Matrix3d R = T_world_link.linear();
  const Eigen::Vector3d& t = T_world_link.translation();
  const bool have_normals = samples.normals.size() == samples.points.size();
  q_world_.clear();
  double loss = 0.0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const Eigen::Vector3d p = R * samples.points[i].cast<double>() + t;
    if (have_normals) {
      const Eigen::Vector3d n = R * samples.normals[i].cast<double>();
      if (visibility_->BestView(p, n, options.visibility_tolerance) != ScanView::kSeen) {
        loss += options.occluded_loss;
        continue;
      }
    }
    q_world_.push_back(p.cast<float>());
  }
  CorrespondenceOptions correspondence;
  correspondence.max_distance = options.max_distance;
  correspondence.window = options.lattice_window;
  correspondence.use_lattice = true;
  search_->Find(q_world_, Eigen::AlignedBox3d(), correspondence, &matches_);
  // Unmatched seen samples: D = max_distance with weight 1.
  loss += static_cast<double>(q_world_.size() - matches_.size()) *
          SweepLoss(options.max_distance, 1.0, options.tau_dist);
  for (const Correspondence& m : matches_) {
    const double w = options.uniform_weights ? 1.0 : std::max(1.0, static_cast<double>(m.weight));
    loss += SweepLoss(static_cast<double>(m.distance), w, options.tau_dist);
  }
  return loss;
}

Status JointSweep::Sweep(const SurfaceSamples& samples, const LinkMotion& motion,
                         const JointSweepOptions& options, JointSweepSummary* summary) {
  CHECK(summary != nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("joint sweep: " + error);
  if (!motion.constrained()) return Status::Error("joint sweep: the link is not on a joint");
  if (samples.points.empty()) return Status::Error("joint sweep: the link has no CAD samples");
  *summary = JointSweepSummary();

  const bool revolute = motion.type == LinkMotion::Type::kRevolute;
  double lower = motion.lower, upper = motion.upper;
  if (!motion.has_limits) {  // continuous joint: one turn (prismatic: none in URDF)
    lower = -M_PI;
    upper = M_PI;
  }
  double step = revolute ? options.revolute_step : options.prismatic_step;
  double best_q = lower, best_loss = std::numeric_limits<double>::infinity();
  auto consider = [&](double q) {
    const double loss = Loss(samples, motion, q, options);
    ++summary->evaluations;
    if (loss < best_loss) {
      best_loss = loss;
      best_q = q;
    }
  };
  const int steps = static_cast<int>(std::floor((upper - lower) / step + 1e-9));
  for (int k = 0; k <= steps; ++k) consider(lower + k * step);
  if (lower + steps * step < upper - 1e-12) consider(upper);
  for (int r = 0; r < options.refinements; ++r) {
    const double centre = best_q;
    const double fine = step / 10.0;
    for (int k = -10; k <= 10; ++k) {
      if (k == 0) continue;
      const double q = centre + k * fine;
      if (motion.has_limits && (q < lower || q > upper)) continue;
      consider(q);
    }
    step = fine;
  }
  summary->q = best_q;
  summary->loss = best_loss;
  summary->mean_loss = best_loss / static_cast<double>(samples.points.size());
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
