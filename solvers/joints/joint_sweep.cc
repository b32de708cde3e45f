#include "solvers/joints/joint_sweep.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

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
  if (!(max_view_gap >= 0.0)) return fail("max_view_gap must be >= 0");
  if (!(visibility_tolerance >= 0.0)) return fail("visibility_tolerance must be >= 0");
  if (lattice_window < 0) return fail("lattice_window must be >= 0");
  if (!(distinct_revolute > 0.0) || !(distinct_prismatic > 0.0)) {
    return fail("distinct_revolute and distinct_prismatic must be > 0");
  }
  return true;
}

JointSweep::JointSweep(const LatticeSearch* lattice, const ScanVisibility* visibility)
    : lattice_(lattice), visibility_(visibility) {
  CHECK(lattice_ != nullptr && visibility_ != nullptr);
}

double JointSweep::SampleLoss(const Eigen::Vector3d& p, const Eigen::Vector3d* n,
                              const JointSweepOptions& options, bool* seen) const {
  *seen = n == nullptr ||
          visibility_->BestView(p, *n, options.visibility_tolerance, /*facing_only=*/false,
                                options.max_view_gap) == ScanView::kSeen;
  if (!*seen) return options.occluded_loss;
  const float max_d2 = static_cast<float>(options.max_distance * options.max_distance);
  const Correspondence m = lattice_->Nearest(p.cast<float>(), options.lattice_window, max_d2);
  // A seen sample without a scan point within max_distance: D = max_distance, w = 1.
  if (m.scan < 0) return SweepLoss(options.max_distance, 1.0, options.tau_dist);
  const double w =
      std::max(1.0, static_cast<double>(m.weight));  // uniform: a search without weights
  return SweepLoss(static_cast<double>(m.distance), w, options.tau_dist);
}

double JointSweep::LossAt(const SurfaceSamples& samples, const Pose& T_world_link,
                          const JointSweepOptions& options, std::vector<float>* losses) const {
  const Eigen::Matrix3d R = T_world_link.linear();
  const Eigen::Vector3d& t = T_world_link.translation();
  const bool have_normals = samples.normals.size() == samples.points.size();
  if (losses != nullptr) losses->resize(samples.points.size());
  double loss = 0.0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const Eigen::Vector3d p = R * samples.points[i].cast<double>() + t;
    const Eigen::Vector3d n = have_normals ? Eigen::Vector3d(R * samples.normals[i].cast<double>())
                                           : Eigen::Vector3d::Zero();
    bool seen = true;
    const double l = SampleLoss(p, have_normals ? &n : nullptr, options, &seen);
    loss += l;
    if (losses != nullptr) (*losses)[i] = seen ? static_cast<float>(l) : -1.0f;
  }
  return loss;
}

void SweptRange(const LinkMotion& motion, double* lower, double* upper) {
  *lower = motion.lower;
  *upper = motion.upper;
  if (!motion.has_limits) {  // continuous joint: one turn (prismatic: none in URDF)
    *lower = -M_PI;
    *upper = M_PI;
  } else if (motion.type == LinkMotion::Type::kRevolute && *upper - *lower > 2.0 * M_PI) {
    // Over a turn of range: every pose has a value within one turn (the one
    // nearest zero when the limits hold it), so sweep that turn only.
    *lower = std::max(*lower, std::min(-M_PI, *upper - 2.0 * M_PI));
    *upper = *lower + 2.0 * M_PI;
  }
}

std::vector<double> SweepValues(double lower, double upper, double step) {
  std::vector<double> values;
  const int n = static_cast<int>(std::floor((upper - lower) / step + 1e-9));
  for (int k = 0; k <= n; ++k) values.push_back(lower + k * step);
  if (values.back() < upper - 1e-12) values.push_back(upper);
  return values;
}

Status JointSweep::Sweep(const SurfaceSamples& samples, const LinkMotion& motion,
                         const JointSweepOptions& options, JointSweepSummary* summary) const {
  CHECK(summary != nullptr);
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("joint sweep: " + error);
  if (!motion.constrained()) return Status::Error("joint sweep: the link is not on a joint");
  if (samples.points.empty()) return Status::Error("joint sweep: the link has no CAD samples");
  *summary = JointSweepSummary();

  const bool revolute = motion.type == LinkMotion::Type::kRevolute;
  double lower, upper;
  SweptRange(motion, &lower, &upper);
  const double coarse = revolute ? options.revolute_step : options.prismatic_step;
  // Losses of several joint values, in parallel: each is a serial sum, so
  // the result does not depend on the thread count.
  auto evaluate_all = [&](const std::vector<double>& q, std::vector<double>* loss) {
    loss->resize(q.size());
    const int64_t n = static_cast<int64_t>(q.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (int64_t k = 0; k < n; ++k) {
      (*loss)[static_cast<size_t>(k)] = Loss(samples, motion, q[static_cast<size_t>(k)], options);
    }
    summary->evaluations += static_cast<int>(n);
  };
  // The coarse profile over the whole range.
  const std::vector<double> qs = SweepValues(lower, upper, coarse);
  std::vector<double> losses;
  evaluate_all(qs, &losses);
  // Coarse to fine around a start: +/- one step at a tenth of it.
  auto refine = [&](double q, double loss, double* best_q, double* best_loss) {
    double step = coarse;
    std::vector<double> candidates, candidate_losses;
    for (int r = 0; r < options.refinements; ++r) {
      const double fine = step / 10.0;
      candidates.clear();
      for (int k = -10; k <= 10; ++k) {
        const double candidate = q + k * fine;
        if (k == 0 || (motion.has_limits && (candidate < lower || candidate > upper))) continue;
        candidates.push_back(candidate);
      }
      evaluate_all(candidates, &candidate_losses);
      for (size_t k = 0; k < candidates.size(); ++k) {  // in order: the first of equals wins
        if (candidate_losses[k] < loss) {
          loss = candidate_losses[k];
          q = candidates[k];
        }
      }
      step = fine;
    }
    *best_q = q;
    *best_loss = loss;
  };
  const size_t n = qs.size();
  const size_t best =
      static_cast<size_t>(std::min_element(losses.begin(), losses.end()) - losses.begin());
  refine(qs[best], losses[best], &summary->q, &summary->loss);

  // The runner-up: the lowest coarse local minimum at least `distinct` from
  // the best (a full turn wraps around).
  const bool full_turn = revolute && upper - lower >= 2.0 * M_PI - 1.5 * coarse;
  const double distinct = revolute ? options.distinct_revolute : options.distinct_prismatic;
  auto distance = [&](double a, double b) {  // a range over a turn holds aliases
    return full_turn ? std::abs(std::remainder(a - b, 2.0 * M_PI)) : std::abs(a - b);
  };
  size_t runner_up = n;
  for (size_t k = 0; k < n; ++k) {
    const bool has_left = k > 0 || full_turn, has_right = k + 1 < n || full_turn;
    const double left = has_left ? losses[(k + n - 1) % n] : losses[k];
    const double right = has_right ? losses[(k + 1) % n] : losses[k];
    if (losses[k] > left || losses[k] > right) continue;
    if (distance(qs[k], summary->q) < distinct) continue;
    if (runner_up == n || losses[k] < losses[runner_up]) runner_up = k;
  }
  if (runner_up < n) {
    summary->has_runner_up = true;
    refine(qs[runner_up], losses[runner_up], &summary->runner_up_q, &summary->runner_up_loss);
  }
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace edgefit
