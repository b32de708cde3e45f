// The whole chain refined at once, and its covariance (stages.h).
#include <chrono>
#include <cstdio>

#include "edgefit/scan/mixed_pixels.h"
#include "solvers/refinement/chain_refinement.h"
#include "solvers/refinement/coverings.h"
#include "stages.h"

namespace edgefit {

std::vector<SurfaceSamples> ChainSamples(const KinematicModel& model, const CadSamples& cad,
                                         const FitOptions& options) {
  std::vector<SurfaceSamples> chain_samples(model.links().size());
  for (size_t j = 0; j <= model.joints().size(); ++j) {
    const bool root = j == model.joints().size();
    if (!root && !model.joints()[j].IsMoving()) continue;
    const Body body = root ? MakeBody(model, model.root_link(), -1)
                           : MakeBody(model, model.joints()[j].child_link, static_cast<int>(j));
    chain_samples[static_cast<size_t>(body.link)] =
        BodySamples(body, cad.icp, options.samples.max_chain_samples);
  }
  return chain_samples;
}

std::vector<SurfaceSamples> SettlingSamples(const std::vector<SurfaceSamples>& chain,
                                            const FitOptions& options) {
  std::vector<SurfaceSamples> settling = chain;
  for (SurfaceSamples& s : settling) ThinSamples(options.samples.max_settling_chain_samples, &s);
  return settling;
}

CellMask RefinementMissingCells(const ScanSet& scans, const FitOptions& options,
                                const ProgressFn& say, FitResult* result) {
  if (!options.refinement.chain.refine || !options.refine_without_mixed_pixels ||
      options.remove_mixed_pixels) {
    return CellMask();
  }
  const auto start = std::chrono::steady_clock::now();
  size_t mixed_pixels = 0;
  CellMask mixed = FindMixedPixels(scans, options.mixed_pixels, &mixed_pixels);
  result->timings.mixed_pixels += Since(start);
  say("chain: " + std::to_string(mixed_pixels) + " mixed pixels left out of the refinement");
  return mixed;
}

Status CoveringsAtTheEstimate(const KinematicModel& model, const ScanSet& scans,
                              CorrespondenceSearch* search, const CadSamples& cad,
                              const FitOptions& options, const ProgressFn& say, FitResult* result,
                              CellMask* covered) {
  EDGEFIT_RETURN_IF_ERROR(FindCoverings(
      model, scans, search, cad.chain, result->T_world_base, result->q,
      options.refinement.coverings, options.refinement.chain.icp.correspondence.use_lattice,
      covered, &result->coverings));
  char line[200];
  std::snprintf(line, sizeof(line),
                "chain: %zu of %zu matched points lie off the CAD surface over an area "
                "(jackets, covers): left out",
                result->coverings.covered, result->coverings.matched);
  say(line);
  return Status::Ok();
}

Status RefineWholeChain(const KinematicModel& model, const ScanSet& scans, const CellMask& missing,
                        CorrespondenceSearch* search, const CellWeights* weights,
                        const CadSamples& cad, const FitOptions& options, const ProgressFn& say,
                        FitResult* result, CellMask* covered, bool settle_only) {
  covered->clear();
  const auto start = std::chrono::steady_clock::now();
  const ChainRefinementOptions& refinement = options.refinement.chain;
  if (refinement.refine) say("chain: whole-chain refinement (base and every joint at once)");
  // Its scans: their mixed pixels taken as missing
  // (FitOptions::refine_without_mixed_pixels).
  const CellMask* mixed = missing.empty() ? nullptr : &missing;
  CorrespondenceSearch unmixed_search(&scans, weights, nullptr, mixed);
  CorrespondenceSearch* refine_search = mixed != nullptr ? &unmixed_search : search;
  // The covariance (chain.covariance) of the last solve only: the result
  // keeps no other. settle_only: every solve on the thinned samples
  // (CadSampleOptions::max_settling_chain_samples), none with it.
  const CoveringOptions& coverings = options.refinement.coverings;
  const int rounds = refinement.refine ? coverings.rounds : 0;
  ChainRefinementOptions settling = refinement;
  settling.covariance = false;
  auto solve = [&](bool last, CorrespondenceSearch* on) {
    return RefineChain(model, scans, mixed, on, settle_only ? cad.chain_settling : cad.chain,
                       settle_only || !last ? settling : refinement, options.residuals,
                       &result->T_world_base, &result->q, &result->chain_refinement);
  };
  EDGEFIT_RETURN_IF_ERROR(solve(rounds == 0, refine_search));

  // Coverings (jackets, covers) found at the estimate and left out, then
  // the chain refined again without them.
  for (int round = 0; round < rounds; ++round) {
    EDGEFIT_RETURN_IF_ERROR(
        CoveringsAtTheEstimate(model, scans, search, cad, options, say, result, covered));
    CorrespondenceSearch masked_search(&scans, weights, covered, mixed);
    EDGEFIT_RETURN_IF_ERROR(solve(round + 1 == rounds, &masked_search));
  }
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

Status RefineIntoBestBasins(const KinematicModel& model, ChainFitter* chain, const ScanSet& scans,
                            const CellMask& missing, CorrespondenceSearch* search,
                            const CellWeights* weights, const CadSamples& cad,
                            const FitOptions& options, const ProgressFn& say, FitResult* result,
                            std::vector<JointRecord>* records, CellMask* covered) {
  const auto start = std::chrono::steady_clock::now();
  const double refine_before = result->timings.refine;  // this stage's time is added to it
  const CoveringSummary coverings = result->coverings;
  for (int round = 0;; ++round) {
    const bool take = round < options.chain.final_basin_rounds;
    const auto round_start = std::chrono::steady_clock::now();
    bool moved = false;
    EDGEFIT_RETURN_IF_ERROR(
        chain->CheckFinalBasins(result->T_world_base, take, &result->q, records, &moved));
    result->timings.alternatives += Since(round_start);
    char line[160];
    std::snprintf(line, sizeof(line),
                  "final basins: every joint checked at the final values in %.2f s",
                  Since(round_start));
    say(line);
    if (!take || !moved) break;
    say("chain: refining again from the better basins");
    EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, scans, missing, search, weights, cad, options,
                                             say, result, covered));
  }
  result->coverings = coverings;  // the verdict's: the cells left out of the first refinement
  const auto pinning_start = std::chrono::steady_clock::now();
  chain->CheckPinning(result->T_world_base, records, result->q);
  result->timings.alternatives += Since(pinning_start);
  result->timings.refine = refine_before + Since(start);
  return Status::Ok();
}

}  // namespace edgefit
