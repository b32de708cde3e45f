// The stations registered to the fitted model (stages.h).
#include <chrono>
#include <cstdio>

#include "solvers/refinement/coverings.h"
#include "solvers/registration/station_alignment.h"
#include "stages.h"

namespace edgefit {

Status AlignStationsStage(const KinematicModel& model, const ScanSet& scans,
                          CorrespondenceSearch* search, const CellWeights* weights,
                          const CadSamples& cad, const FitOptions& options, const ProgressFn& say,
                          FitResult* result, ScanSet* aligned, bool* done) {
  const StationAlignmentOptions& stations = options.stations;
  *done = stations.align && scans.scans.size() > 1;
  if (!*done) return Status::Ok();
  const auto start = std::chrono::steady_clock::now();
  const int rounds = options.refinement.chain.refine ? stations.rounds : 1;
  for (int round = 0; round < rounds; ++round) {
    if (round > 0) {
      // The chain refined on the stations as last registered, so that the
      // next registration is made at a better estimate.
      CorrespondenceSearch aligned_search(aligned, weights);
      CellMask covered;
      EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, *aligned, &aligned_search, weights, cad,
                                               options, say, result, &covered));
    }
    // Coverings (jackets) would pull a station towards the side it sees them
    // on: found at this estimate and left out, and with them the links they
    // mostly cover.
    CellMask covered;
    CoveringSummary coverings;
    const bool find_coverings = options.refinement.coverings.rounds > 0;
    if (find_coverings) {
      EDGEFIT_RETURN_IF_ERROR(FindCoverings(
          model, scans, search, cad.chain, result->T_world_base, result->q,
          options.refinement.coverings, options.refinement.chain.icp.correspondence.use_lattice,
          &covered, &coverings));
    }
    const StationAlignmentSummary last = result->stations;
    if (round == 0) {
      *aligned = scans;
    } else {  // registered again from the written poses
      for (size_t k = 0; k < scans.scans.size(); ++k) {
        aligned->scans[k].set_T_world_scanner(scans.scans[k].T_world_scanner());
      }
    }
    const std::vector<uint8_t> left_out =
        find_coverings ? coverings.LinksCoveredOver(stations.max_covered_share)
                       : std::vector<uint8_t>();
    EDGEFIT_RETURN_IF_ERROR(AlignStationsToModel(model, cad.chain, result->T_world_base, result->q,
                                                 find_coverings ? &covered : nullptr, left_out,
                                                 stations, aligned, &result->stations));
    result->stations.rounds = round + 1;
    say(StationAlignmentLine(result->stations));
    // The stations agree as written, or their corrections settled.
    if (round == 0) {
      if (LargestCorrection(result->stations) <= stations.refit_correction) break;
      continue;
    }
    const double change = LargestChange(last, result->stations, scans);
    char line[160];
    std::snprintf(line, sizeof(line),
                  "stations: registered again at the refined estimate (round %d): corrections "
                  "changed by up to %.2f mm at 5 m",
                  round + 1, 1e3 * change);
    say(line);
    if (change <= stations.refit_correction) break;
  }
  result->timings.stations = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
