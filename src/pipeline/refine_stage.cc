// The whole chain refined at once, and its covariance (stages.h).
#include <chrono>
#include <cstdio>

#include "solvers/refinement/chain_refinement.h"
#include "stages.h"

namespace edgefit {

Status RefineWholeChain(const KinematicModel& model, const ScanSet& scans,
                        CorrespondenceSearch* search, const CadSamples& cad,
                        const FitOptions& options, const ProgressFn& say, FitResult* result) {
  const auto start = std::chrono::steady_clock::now();
  const ChainRefinementOptions& refinement = options.refinement.chain;
  if (refinement.refine) say("chain: whole-chain refinement (base and every joint at once)");
  // The samples of every moving body (and the base) in its link's frame;
  // prismatic bodies keep point-to-point residuals, as in their joint ICP.
  std::vector<SurfaceSamples> chain_samples(model.links().size());
  std::vector<bool> point_to_point(model.links().size(), false);
  for (size_t j = 0; j <= model.joints().size(); ++j) {
    const bool root = j == model.joints().size();
    if (!root && !model.joints()[j].IsMoving()) continue;
    const Body body = root ? MakeBody(model, model.root_link(), -1)
                           : MakeBody(model, model.joints()[j].child_link, static_cast<int>(j));
    chain_samples[static_cast<size_t>(body.link)] =
        BodySamples(body, cad.icp, options.samples.max_chain_samples);
    point_to_point[static_cast<size_t>(body.link)] =
        !root && model.joints()[j].type == JointType::kPrismatic;
  }
  EDGEFIT_RETURN_IF_ERROR(RefineChain(model, scans, search, chain_samples, point_to_point,
                                      refinement, options.residuals, &result->T_world_base,
                                      &result->q, &result->chain_refinement));
  result->timings.refine = Since(start);
  if (refinement.refine) {
    char line[200];
    std::snprintf(line, sizeof(line),
                  "chain: refined in %d iterations (%s), samples moved up to %.3f mm, %.2f s",
                  result->chain_refinement.iterations,
                  IcpStopReasonName(result->chain_refinement.stop_reason),
                  1e3 * result->chain_refinement.max_displacement, result->timings.refine);
    say(line);
  }
  return Status::Ok();
}

}  // namespace edgefit
