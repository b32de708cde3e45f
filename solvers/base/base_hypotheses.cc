#include "solvers/base/base_hypotheses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace edgefit {

bool BaseHypothesesOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(slide_elongation > 0.0) || !(slide_step > 0.0)) {
    return fail("slide_elongation and slide_step must be > 0");
  }
  if (alternatives < 0 || !(alternative_loss >= 0.0)) {
    return fail("base alternatives and alternative_loss must be >= 0");
  }
  if (!(instance_separation > 0.0)) return fail("instance_separation must be > 0");
  return true;
}

bool IsDistinctPose(const Pose& a, const Pose& b) {
  const Pose d = a.inverse() * b;
  return Eigen::AngleAxisd(d.linear()).angle() > 5.0 * M_PI / 180.0 ||
         d.translation().norm() > 0.05;
}

Pose SlideAlong(const Pose& T_world_base, const Eigen::Vector3d& axis_base, double range,
                double step, const BasePoseLoss& loss) {
  const Eigen::Vector3d axis_world = T_world_base.linear() * axis_base;
  auto moved = [&](double d) {
    Pose T = T_world_base;
    T.translation() += d * axis_world;
    return T;
  };
  auto best_of = [&](double from, double to, double by) {
    const int n = static_cast<int>(std::ceil((to - from) / by));
    std::vector<double> losses(static_cast<size_t>(n) + 1);
#pragma omp parallel for schedule(dynamic, 8)
    for (int k = 0; k <= n; ++k) losses[static_cast<size_t>(k)] = loss(moved(from + k * by));
    const size_t best =
        static_cast<size_t>(std::min_element(losses.begin(), losses.end()) - losses.begin());
    return from + static_cast<double>(best) * by;
  };
  const double coarse = best_of(-range, range, step);
  return moved(best_of(coarse - step, coarse + step, 0.2 * step));
}

std::vector<Pose> RankBaseHypotheses(std::vector<Pose>* candidates,
                                     const Eigen::Vector3d& base_size, bool slide,
                                     const BasePoseLoss& loss, size_t samples,
                                     const BaseHypothesesOptions& options,
                                     const std::function<void(const std::string&)>& say) {
  const int along = base_size.x() >= base_size.y() ? 0 : 1;
  if (slide && base_size[along] > options.slide_elongation * std::max(base_size[1 - along], 1e-9)) {
    say("base: elongated; each candidate slides along its length (Eq. 9 loss of the base)");
    for (Pose& candidate : *candidates) {
      candidate = SlideAlong(candidate, Eigen::Vector3d::Unit(along), 0.5 * base_size[along],
                             options.slide_step, loss);
    }
  }
  std::vector<std::pair<double, Pose>> by_loss;
  for (const Pose& candidate : *candidates) by_loss.emplace_back(loss(candidate), candidate);
  std::stable_sort(by_loss.begin(), by_loss.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Pose> roughs;
  for (const auto& [candidate_loss, candidate] : by_loss) {
    const double margin = (candidate_loss - by_loss.front().first) / static_cast<double>(samples);
    bool distinct = true;
    for (const Pose& kept : roughs) distinct = distinct && IsDistinctPose(kept, candidate);
    if (!roughs.empty() && (!distinct || margin >= options.alternative_loss)) continue;
    if (static_cast<int>(roughs.size()) > options.alternatives) break;
    if (!roughs.empty()) {
      char line[160];
      std::snprintf(line, sizeof(line),
                    "base: a distinct rough pose only %.3f mm/sample worse: fitted too",
                    1e3 * margin);
      say(line);
    }
    roughs.push_back(candidate);
  }
  return roughs;
}

}  // namespace edgefit
