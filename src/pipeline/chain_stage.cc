// Sec. 5.1.2 and 5.2-5.3: the base's precise ICP and the chain, from each
// rough base pose kept (stages.h).
#include <chrono>
#include <cstdio>
#include <limits>
#include <utility>

#include "stages.h"

namespace edgefit {

Status FitChainFrom(const KinematicModel& model, const Body& base,
                    const SurfaceSamples& base_samples, const RoughPose& rough,
                    const FitOptions& options, WeightedIcp* icp, ChainFitter* chain,
                    const ProgressFn& say, FitResult* result, ChainAttempt* attempt) {
  auto stage = std::chrono::steady_clock::now();
  LinkState base_state;
  base_state.T_world_link = rough.T_world_base;
  if (rough.registered) {
    EDGEFIT_RETURN_IF_ERROR(
        icp->Evaluate(base_samples, rough.T_world_base, options.base.icp, &attempt->base));
  } else {
    say("base: precise weighted ICP");
    EDGEFIT_RETURN_IF_ERROR(
        icp->Fit(base_samples, LinkMotion::Free(), options.base.icp, &base_state, &attempt->base));
  }
  attempt->T_world_base = base_state.T_world_link;
  result->timings.base_precise += Since(stage);
  if (options.min_base_inlier_share > 0.0 &&
      Quality(model, base, base_samples, attempt->base, options.quality).inlier_share <
          options.min_base_inlier_share) {
    attempt->base_mismatch = true;
    attempt->loss = std::numeric_limits<double>::infinity();
    return Status::Ok();
  }
  stage = std::chrono::steady_clock::now();
  EDGEFIT_RETURN_IF_ERROR(
      chain->Fit(attempt->T_world_base, &attempt->q, &attempt->records, &attempt->loss));
  result->timings.chain += Since(stage);
  return Status::Ok();
}

Status FitChainFromRoughPoses(const KinematicModel& model, const Body& base,
                              const SurfaceSamples& base_samples,
                              const std::vector<RoughPose>& roughs,
                              const FitOptions& options, WeightedIcp* icp, ChainFitter* chain,
                              const ProgressFn& say, FitResult* result, ChainAttempt* best) {
  EDGEFIT_RETURN_IF_ERROR(FitChainFrom(model, base, base_samples, roughs.front(), options, icp,
                                       chain, say, result, best));
  const auto start = std::chrono::steady_clock::now();
  for (size_t k = 1; k < roughs.size(); ++k) {
    const double apart =
        (roughs[k].T_world_base.translation() - roughs.front().T_world_base.translation()).norm();
    char line[240];
    if (apart > options.base.hypotheses.instance_separation && !best->base_mismatch) {
      std::snprintf(line, sizeof(line),
                    "base: alternative rough pose %zu stands %.2f m away: another machine's "
                    "place, not fitted",
                    k, apart);
      say(line);
      continue;
    }
    const Eigen::Vector3d& t = roughs[k].T_world_base.translation();
    std::snprintf(line, sizeof(line),
                  "base: the whole chain from alternative rough pose %zu at %.3f, %.3f, %.3f m",
                  k, t.x(), t.y(), t.z());
    say(line);
    ChainAttempt other;
    EDGEFIT_RETURN_IF_ERROR(FitChainFrom(model, base, base_samples, roughs[k], options, icp, chain,
                                         say, result, &other));
    std::snprintf(line, sizeof(line),
                  "base: alternative rough pose %zu: whole model Eq. 9 loss %.1f against %.1f%s", k,
                  other.loss, best->loss, other.loss < best->loss ? ": taken" : "");
    say(line);
    if (other.loss < best->loss) {
      *best = std::move(other);
      result->base_rough.T_world_base = roughs[k].T_world_base;
    }
  }
  result->timings.alternatives = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
