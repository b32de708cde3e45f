// The stations registered to the fitted model (stages.h).
#include <chrono>
#include <cstdio>

#include "solvers/refinement/coverings.h"
#include "solvers/registration/station_alignment.h"
#include "stages.h"

namespace edgefit {

Status AlignStationsStage(const KinematicModel& model, ScanSet* scans, const CellMask& missing,
                          CorrespondenceSearch* search, const CellWeights* weights,
                          const CadSamples& cad, const FitOptions& options, const ProgressFn& say,
                          FitResult* result) {
  const StationAlignmentOptions& stations = options.stations;
  if (!stations.align || scans->scans.size() < 2) return Status::Ok();
  const auto start = std::chrono::steady_clock::now();
  std::vector<Pose> T_written;
  for (const OrganizedScan& scan : scans->scans) T_written.push_back(scan.T_world_scanner());
  const int rounds = options.refinement.chain.refine ? stations.rounds : 1;
  for (int round = 0; round < rounds; ++round) {
    if (round > 0) {
      // The chain refined on the stations as last registered, so that the
      // next registration is made at a better estimate; that one starts
      // from the written poses again, at which `search` was built.
      CorrespondenceSearch aligned_search(scans, weights);
      CellMask covered;
      // An estimate to register at (settle_only: the fit's last refinement
      // has the covariance).
      EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, *scans, missing, &aligned_search, weights,
                                               cad, options, say, result, &covered,
                                               /*settle_only=*/true));
      for (size_t k = 0; k < T_written.size(); ++k) {
        scans->scans[k].set_T_world_scanner(T_written[k]);
      }
    }
    // Coverings (jackets) would pull a station towards the side it sees them
    // on: found at this estimate and left out, and with them the links they
    // mostly cover.
    CellMask covered;
    CoveringSummary coverings;
    const bool find_coverings = options.refinement.coverings.rounds > 0;
    if (find_coverings) {
      EDGEFIT_RETURN_IF_ERROR(FindCoverings(model, *scans, search, cad.chain, result->T_world_base,
                                            result->q, options.refinement.coverings,
                                            options.refinement.chain.icp.correspondence.use_lattice,
                                            &covered, &coverings));
    }
    const StationAlignmentSummary last = result->stations;
    const std::vector<uint8_t> left_out =
        find_coverings ? coverings.LinksCoveredOver(stations.max_covered_share)
                       : std::vector<uint8_t>();
    EDGEFIT_RETURN_IF_ERROR(AlignStationsToModel(model, cad.chain, result->T_world_base, result->q,
                                                 find_coverings ? &covered : nullptr, left_out,
                                                 stations, scans, &result->stations));
    result->stations.rounds = round + 1;
    say(StationAlignmentLine(result->stations));
    // The stations agree as written, or their corrections settled.
    if (round == 0) {
      if (LargestCorrection(result->stations) <= stations.refit_correction) break;
      continue;
    }
    const double change = LargestChange(last, result->stations, T_written);
    char line[160];
    std::snprintf(line, sizeof(line),
                  "stations: registered again at the refined estimate (round %d): corrections "
                  "changed by up to %.2f mm at 5 m",
                  round + 1, 1e3 * change);
    say(line);
    if (change <= stations.settled_change) break;
  }
  result->timings.stations = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
