// The stations registered to the fitted model (stages.h).
#include <chrono>

#include "solvers/refinement/coverings.h"
#include "solvers/registration/station_alignment.h"
#include "stages.h"

namespace edgefit {

Status AlignStationsStage(const KinematicModel& model, const ScanSet& scans,
                          CorrespondenceSearch* search, const CadSamples& cad,
                          const FitOptions& options, const ProgressFn& say, FitResult* result,
                          ScanSet* aligned, bool* done) {
  *done = options.stations.align && scans.scans.size() > 1;
  if (!*done) return Status::Ok();
  const auto start = std::chrono::steady_clock::now();
  // Coverings (jackets) would pull a station towards the side it sees them
  // on: found at this estimate and left out.
  const std::vector<SurfaceSamples>& chain_samples = cad.chain;
  CellMask covered;
  CoveringSummary coverings;
  const bool find_coverings = options.refinement.coverings.rounds > 0;
  if (find_coverings) {
    EDGEFIT_RETURN_IF_ERROR(FindCoverings(
        model, scans, search, chain_samples, result->T_world_base, result->q,
        options.refinement.coverings, options.refinement.chain.icp.correspondence.use_lattice,
        &covered, &coverings));
  }
  *aligned = scans;
  EDGEFIT_RETURN_IF_ERROR(AlignStationsToModel(model, chain_samples, result->T_world_base,
                                               result->q, find_coverings ? &covered : nullptr,
                                               options.stations, aligned, &result->stations));
  result->timings.stations = Since(start);
  say(StationAlignmentLine(result->stations));
  return Status::Ok();
}

}  // namespace edgefit
