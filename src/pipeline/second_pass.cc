// Extension: the chain fitted again on the aligned stations without the
// coverings, then refined and judged there (stages.h).
#include <vector>

#include "stages.h"

namespace edgefit {

Status RefitWithoutCoverings(const KinematicModel& model, const ScanSet& scans,
                             CellMask covered, const ScanTools& first_pass,
                             const Body& base, const SurfaceSamples& base_samples,
                             const CadSamples& cad, const CellWeights* weights,
                             const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner,
                             bool covered_link, const FitOptions& options, const ProgressFn& say,
                             FitResult* result) {
  ScanSet clean_scans = scans;
  for (size_t s = 0; s < covered.size(); ++s) {  // empty without covering rounds
    for (size_t i = 0; i < covered[s].size(); ++i) {
      if (covered[s][i]) clean_scans.scans[s].SetMissing(i);
    }
  }
  covered = CellMask();  // a byte per cell: not held beside this pass's own masks
  ScanTools clean(&clean_scans, weights, normals_scanner, options.residuals);
  ChainFitter chain(model, options.chain, options.samples, cad.icp, cad.sweep, &clean.icp,
                    &clean.sweep, say);
  chain.set_covered_scan(&first_pass.sweep);
  const std::vector<double> q_with_coverings = result->q;
  ChainAttempt refit;
  EDGEFIT_RETURN_IF_ERROR(FitChainFrom(model, base, base_samples, {result->T_world_base}, options,
                                       &clean.icp, &chain, say, result, &refit));
  result->T_world_base = refit.T_world_base;
  result->bodies.front() = Quality(model, base, base_samples, refit.base, options.quality);
  const Status resolved = model.ResolveDependentJoints(&refit.q);
  result->q = refit.q;

  const CoveringSummary first_coverings = result->coverings;
  const CellMask mixed = RefinementMissingCells(clean_scans, options, say, result);
  CellMask still_covered;
  EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, clean_scans, mixed, &clean.search, weights, cad,
                                           options, say, result, &still_covered));
  result->coverings = first_coverings;  // the cells left out of this pass
  EDGEFIT_RETURN_IF_ERROR(RefineIntoBestBasins(model, &chain, clean_scans, mixed, &clean.search,
                                               weights, cad, options, say, result, &refit.records,
                                               &still_covered));
  EDGEFIT_RETURN_IF_ERROR(
      JudgeQuality(model, &clean.icp, cad, refit.records, resolved, options, result));
  if (covered_link) MarkBasinChanges(model, chain, q_with_coverings, options, say, result);
  return Status::Ok();
}

}  // namespace edgefit
