// The stages of Fit() (fit.h) that are more than one call into solvers/:
// each reads the options of its stage and writes its part of the result.
// Internal to edgefit::pipeline.
#ifndef EDGEFIT_SRC_PIPELINE_STAGES_H_
#define EDGEFIT_SRC_PIPELINE_STAGES_H_

#include <Eigen/Core>
#include <chrono>
#include <string>
#include <vector>

#include "edgefit/correspondence/correspondence_search.h"
#include "edgefit/model/kinematic_model.h"
#include "edgefit/model/surface_sampler.h"
#include "edgefit/pipeline/fit.h"
#include "solvers/joints/body.h"
#include "solvers/joints/chain_fitter.h"
#include "solvers/joints/joint_sweep.h"
#include "solvers/joints/observability.h"
#include "solvers/refinement/coverings.h"
#include "solvers/registration/scan_visibility.h"
#include "solvers/registration/weighted_icp.h"

namespace edgefit {

// Seconds since `start` (the stages' timings).
inline double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether the scans are a depth camera's frames (projective lattices).
inline bool AnyCameraFrame(const ScanSet& scans) {
  for (const OrganizedScan& scan : scans.scans) {
    if (scan.lattice().valid() && scan.lattice().model() == ScanLattice::Model::kProjective) {
      return true;
    }
  }
  return false;
}

// The CAD samples of every link (model.links() order, link frame): dense
// for the precise stages, sparse for the sweeps; and per body for the
// whole-chain stages (stations, refinement, coverings), made once by
// ChainSamples.
struct CadSamples {
  // chain_settling: chain thinned to CadSampleOptions::max_settling_chain_samples.
  std::vector<SurfaceSamples> icp, sweep, chain, chain_settling;
};

// What the stages search and fit with on one scan set: the nearest scan
// points, which samples the scans see, the weighted ICP and the Eq. (9)
// sweep. Borrows `scans` (and the weights and normals): searches built on
// a scan set are stale once its stations move.
struct ScanTools {
  ScanTools(const ScanSet* scans, const CellWeights* weights,
            const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner,
            const ResidualOptions& residuals)
      : search(scans, weights),
        visibility(scans),
        icp(scans, &search, normals_scanner, residuals),
        sweep(&search.lattice(), &visibility) {}
  CorrespondenceSearch search;
  const ScanVisibility visibility;
  WeightedIcp icp;
  const JointSweep sweep;
};

// A rough base pose; `registered`: already registered to the scans with
// the first links (any mounting: the base body alone, round on many arms,
// would turn on its ICP), so the chain starts from it as it is.
struct RoughPose {
  Pose T_world_base = Pose::Identity();
  bool registered = false;
};

// A fit of the base and the chain from one rough base pose.
struct ChainAttempt {
  Pose T_world_base = Pose::Identity();
  WeightedIcpSummary base;  // the base's precise ICP (Sec. 5.1.2)
  std::vector<double> q;
  std::vector<JointRecord> records;
  double loss = 0.0;           // Eq. (9) of the whole model
  bool base_mismatch = false;  // FitOptions::min_base_inlier_share: the chain was not fitted
};

// Sec. 5.1.2 and 5.2-5.3 from `rough`: the base's precise weighted ICP
// (base_samples: the base body's; for a registered rough pose its quality
// alone), then every joint, parents first (`chain`, on the scans of `icp`). A base whose inlier share is below
// FitOptions::min_base_inlier_share is a mismatch: the chain is not fitted
// and the loss is infinite. Adds to result->timings.
Status FitChainFrom(const KinematicModel& model, const Body& base,
                    const SurfaceSamples& base_samples, const RoughPose& rough,
                    const FitOptions& options, WeightedIcp* icp, ChainFitter* chain,
                    const ProgressFn& say, FitResult* result, ChainAttempt* attempt);

// FitChainFrom from the first rough pose and from every alternative
// standing within BaseHypothesesOptions::instance_separation of it (others
// are another machine's place); the lowest Eq. (9) loss of the whole model
// wins (result->base_rough records the rough pose it came from).
Status FitChainFromRoughPoses(const KinematicModel& model, const Body& base,
                              const SurfaceSamples& base_samples,
                              const std::vector<RoughPose>& roughs,
                              const FitOptions& options, WeightedIcp* icp, ChainFitter* chain,
                              const ProgressFn& say, FitResult* result, ChainAttempt* best);

// Extension: the sequential fit chose every joint's basin on stations that
// did not agree, or with coverings hiding much of a link: the chain again
// from result->T_world_base on `scans` (the aligned stations) without the
// `covered` cells (taken: freed once they are left out), then the
// refinement, the final basins and the verdict there. `first_pass`: the
// tools on `scans` with the coverings, whose sweep tells what the coverings
// hide. result->coverings keeps the first pass's.
Status RefitWithoutCoverings(const KinematicModel& model, const ScanSet& scans,
                             CellMask covered, const ScanTools& first_pass,
                             const Body& base, const SurfaceSamples& base_samples,
                             const CadSamples& cad, const CellWeights* weights,
                             const std::vector<std::vector<Eigen::Vector3f>>* normals_scanner,
                             bool covered_link, const FitOptions& options, const ProgressFn& say,
                             FitResult* result);

// Extension for noisy sensors (noise_scale.h): the base body registered
// from T_rough with options.noise.gate fixed, sigma from its matches'
// median distance into result->noise_sigma, the scale into
// result->noise_scale, and *scaled: `options` with every distance threshold
// scaled (`options` itself when options.noise.scale is off).
Status MeasureNoise(const SurfaceSamples& base_samples, const Pose& T_rough,
                    const FitOptions& options, WeightedIcp* icp, const ProgressFn& say,
                    FitResult* result, FitOptions* scaled);

// Any mounting (BaseOptions::Mounting; mounting_stage.cc): the base with
// its first links voted for on oriented point pairs in several postures,
// each vote registered, ranked by its body's evidence (pose_evidence.h),
// ties by its Eq. (9) loss per sample; the best BaseOptions::voted_roughs
// distinct poses into *roughs, best first.
// Fails when no pair of the scans matches the model's.
Status VoteBasePoses(const KinematicModel& model, const ScanSet& scans, const Body& base,
                     const CadSamples& cad, const FitOptions& options, ScanTools* tools,
                     const ProgressFn& say, std::vector<RoughPose>* roughs);

// Sec. 5.1.1 / 6.1: the rough base poses to fit from, best first, into
// *roughs (result->base_rough, arm_tips and base_rough_method record how):
// from options.base's hint, or the rough stage of its method ranked by the
// Eq. (9) loss of the base alone (base_hypotheses.h). An error means the
// scan gave no base pose (the fit is not ok), never bad options.
Status RoughBasePoses(const KinematicModel& model, const ScanSet& scans, const Body& base,
                      const CadSamples& cad, ScanTools* tools, const FitOptions& options,
                      const ProgressFn& say, FitResult* result, std::vector<RoughPose>* roughs);

// The samples of every moving body (and the base) in its link's frame,
// model.links() order (empty for links without a body of their own).
std::vector<SurfaceSamples> ChainSamples(const KinematicModel& model, const CadSamples& cad,
                                         const FitOptions& options);
// Those samples thinned for the refinements between the station
// registrations (CadSampleOptions::max_settling_chain_samples).
std::vector<SurfaceSamples> SettlingSamples(const std::vector<SurfaceSamples>& chain,
                                            const FitOptions& options);

// The cells of `scans` the whole-chain refinement takes as missing: their
// mixed pixels (FitOptions::refine_without_mixed_pixels), found once per
// scan set (they do not move with the stations' poses); empty when the
// refinement keeps them. Its time is added to result->timings.mixed_pixels.
CellMask RefinementMissingCells(const ScanSet& scans, const FitOptions& options,
                                const ProgressFn& say, FitResult* result);

// The coverings (options.refinement.coverings: jackets, covers) of `scans`
// at result's estimate, by `search`, into *covered and result->coverings.
Status CoveringsAtTheEstimate(const KinematicModel& model, const ScanSet& scans,
                              CorrespondenceSearch* search, const CadSamples& cad,
                              const FitOptions& options, const ProgressFn& say, FitResult* result,
                              CellMask* covered);

// The whole chain refined at once (options.refinement), or its covariance
// alone, from result->T_world_base and result->q, in place; then, for
// options.refinement.coverings.rounds, refined again without the coverings
// found at the estimate. The refinement takes the `missing` cells of
// `scans` (RefinementMissingCells; empty: none) as missing, the coverings
// are found on `scans` as they are. weights: the search's (nullptr:
// uniform). *covered: the last round's coverings (empty without rounds).
// The covariance (options.refinement.chain.covariance) is the last solve's.
// settle_only: an estimate to register the stations at: every solve on
// cad.chain_settling, none with the covariance.
Status RefineWholeChain(const KinematicModel& model, const ScanSet& scans, const CellMask& missing,
                        CorrespondenceSearch* search, const CellWeights* weights,
                        const CadSamples& cad, const FitOptions& options, const ProgressFn& say,
                        FitResult* result, CellMask* covered, bool settle_only = false);

// Extension: every joint's basin checked at the final values
// (ChainFitter::CheckFinalBasins, with `chain` on the same scans as
// `search`); the branches that fit better elsewhere are taken and the
// whole chain is refined again from there (RefineWholeChain), for up to
// ChainOptions::final_basin_rounds rounds while a round takes one; a joint
// better elsewhere after the last is marked in *records. Last,
// whether the scan pins each revolute joint at the final values
// (CheckPinning).
Status RefineIntoBestBasins(const KinematicModel& model, ChainFitter* chain, const ScanSet& scans,
                            const CellMask& missing, CorrespondenceSearch* search,
                            const CellWeights* weights, const CadSamples& cad,
                            const FitOptions& options, const ProgressFn& say, FitResult* result,
                            std::vector<JointRecord>* records, CellMask* covered);

// The verdict of every jointed body alone at the final values (the base's
// is in result->bodies already), appended to result->bodies; result->ok
// and result->message from them and from `resolved` (the dependent joints;
// SayWhyNotOk). First the reporting conventions move result->q: a joint
// the geometry cannot pin (TurnIsUnobservable) to its zero or the limit
// nearest it, a joint with a range beyond a full turn to its whole turn
// nearest zero (each places every link as the fitted value does).
Status JudgeQuality(const KinematicModel& model, WeightedIcp* icp, const CadSamples& cad,
                    const std::vector<JointRecord>& records, const Status& resolved,
                    const FitOptions& options, FitResult* result);

// result->ok: `resolved` is ok and so is every body (result->bodies);
// result->message: why not, a clause per body that is not, joined by "; ".
void SayWhyNotOk(const KinematicModel& model, const Status& resolved, const FitOptions& options,
                 FitResult* result);

// Extension: every station registered to the model at result's estimate
// (options.stations), the coverings found there left out; then, while the
// corrections have not settled (StationAlignmentOptions::rounds, settle),
// the chain refined on the corrected stations (RefineWholeChain: result's
// estimate moves) and the stations registered again there. *scans get the
// last corrections in place (with more than one station and
// options.stations.align). search: over *scans at their poses on entry
// (as written); searches built on them before are stale after. missing:
// RefinementMissingCells of *scans.
Status AlignStationsStage(const KinematicModel& model, ScanSet* scans, const CellMask& missing,
                          CorrespondenceSearch* search, const CellWeights* weights,
                          const CadSamples& cad, const FitOptions& options, const ProgressFn& say,
                          FitResult* result);

// After the second pass (the chain fitted again without the coverings): a
// revolute joint more than options.refinement.coverings.basin_change from
// its value in q_first (the first pass's, with the coverings), and no joint
// above it, is a change of basin. The two are compared on the scan without
// the coverings (`chain`'s) as branches are (ChainFitter::BranchGain):
// unless the final values fit the bodies they place apart better by
// options.chain.ambiguity_mean_loss per sample of the subtree, the joint is
// ambiguous and the fit not ok.
void MarkBasinChanges(const KinematicModel& model, const ChainFitter& chain,
                      const std::vector<double>& q_first, const FitOptions& options,
                      const ProgressFn& say, FitResult* result);

// The quality of a body from an ICP summary at its final pose.
BodyQuality Quality(const KinematicModel& model, const Body& body, const SurfaceSamples& samples,
                    const WeightedIcpSummary& summary, const QualityOptions& options);

}  // namespace edgefit

#endif  // EDGEFIT_SRC_PIPELINE_STAGES_H_
