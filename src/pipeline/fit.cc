// Fit(): the paper's pipeline, stage by stage (fit.h).
#include "edgefit/pipeline/fit.h"

#include <glog/logging.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <utility>

#include "edgefit/correspondence/correspondence_search.h"
#include "solvers/registration/scan_visibility.h"
#include "solvers/registration/station_alignment.h"
#include "stages.h"

namespace edgefit {
namespace {

// A fit from one rough base pose: the base's precise ICP, then every joint.
struct Attempt {
  Pose T_world_base = Pose::Identity();
  WeightedIcpSummary base;
  std::vector<double> q;
  std::vector<JointRecord> records;
  double loss = 0.0;           // Eq. (9) of the whole model
  bool base_mismatch = false;  // FitOptions::min_base_inlier_share: the chain was not fitted
};

// Options, a root link, a model in metres, and scans on their lattices.
Status CheckFitInputs(const KinematicModel& model, const ScanSet& scans,
                      const FitOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return Status::Error("robot fit: " + error);
  for (size_t s = 0; s < scans.scans.size(); ++s) {
    const OrganizedScan& scan = scans.scans[s];
    if (!scan.organized() || !scan.lattice().valid() || scan.lattice().rows() != scan.rows() ||
        scan.lattice().cols() != scan.cols()) {
      return Status::Error(
          "scan " + std::to_string(s) +
          (s < scans.sources.size() ? " (" + scans.sources[s] + ")" : std::string()) +
          ": the fit needs an organized scan on its angular lattice (PTX, E57 with row and "
          "column indices, organized PCD), not a point list");
    }
  }
  if (model.root_link() < 0) return Status::Error("robot fit: the model has no root link");
  const Eigen::Vector3d extent = model.BoundingBox(model.ZeroJoints(), Pose::Identity()).sizes();
  if (!(extent.maxCoeff() <= options.samples.max_model_extent)) {
    char line[300];
    std::snprintf(line, sizeof(line),
                  "the model spans %.4g m at its zero posture (more than %.0f m): URDF lengths "
                  "are metres; is it written in millimetres?",
                  extent.maxCoeff(), options.samples.max_model_extent);
    const std::string& source = model.links()[static_cast<size_t>(model.root_link())].source;
    return Status::Error(source.empty() ? std::string(line) : source + ": " + line);
  }
  return Status::Ok();
}

}  // namespace

Status Fit(const KinematicModel& model, const ScanSet& written_scans, const FitOptions& options,
           const ProgressFn& progress, FitResult* result) {
  CHECK(result != nullptr);
  EDGEFIT_RETURN_IF_ERROR(CheckFitInputs(model, written_scans, options));  // before any work
  const auto start = std::chrono::steady_clock::now();
  // Extension: mixed pixels off the scans.
  ScanSet without_mixed;
  size_t mixed_pixels = 0;
  if (options.remove_mixed_pixels) {
    without_mixed = WithoutMixedPixels(written_scans, options.mixed_pixels, &mixed_pixels);
    if (progress) progress("mixed pixels: " + std::to_string(mixed_pixels) + " removed");
  }
  const ScanSet& scans = options.remove_mixed_pixels ? without_mixed : written_scans;
  const double mixed_seconds = Since(start);

  // Sec. 4: edge weights and normals, when the weighting uses them.
  const auto edges_start = std::chrono::steady_clock::now();
  EdgeDetectionResult edges;
  if (!options.uniform_weights) {
    if (progress) progress("edges: detecting on " + std::to_string(scans.TotalValid()) + " points");
    EDGEFIT_RETURN_IF_ERROR(DetectEdges(scans, options.edges, &edges));
  }
  const double edge_seconds = Since(edges_start);
  EDGEFIT_RETURN_IF_ERROR(FitWithEdges(model, scans, edges, options, progress, result));
  result->mixed_pixels = mixed_pixels;
  result->timings.edges = edge_seconds;
  result->timings.mixed_pixels += mixed_seconds;
  result->timings.total += edge_seconds + mixed_seconds;
  return Status::Ok();
}

Status FitWithEdges(const KinematicModel& model, const ScanSet& scans,
                    const EdgeDetectionResult& edges, const FitOptions& options,
                    const ProgressFn& progress, FitResult* result) {
  CHECK(result != nullptr);
  const auto start = std::chrono::steady_clock::now();
  auto say = [&progress](const std::string& line) {
    if (progress) progress(line);
  };
  EDGEFIT_RETURN_IF_ERROR(CheckFitInputs(model, scans, options));
  if (!options.uniform_weights && edges.w_edge.size() != scans.scans.size()) {
    return Status::Error("robot fit: edge weighting needs the scans' edges (Sec. 4)");
  }
  *result = FitResult();
  auto not_ok = [&](const std::string& message) {
    result->ok = false;
    result->message = message;
    result->q = model.ZeroJoints();
    result->timings.total = Since(start);
    return Status::Ok();
  };

  // CAD samples: dense for the ICP stages, sparse for the sweeps.
  SamplingOptions sampling;
  sampling.seed = options.seed;
  CadSamples cad;
  sampling.spacing = options.samples.icp_spacing;
  cad.icp = SampleModelSurfaces(model, sampling);
  sampling.spacing = options.samples.sweep_spacing;
  cad.sweep = SampleModelSurfaces(model, sampling);
  cad.chain = ChainSamples(model, cad, options);

  const CellWeights* weights = options.uniform_weights ? nullptr : &edges.w_edge;
  const auto* scan_normals = edges.normals.empty() ? nullptr : &edges.normals;

  // Sec. 5.1.1 / 6.1: the base body's rough poses.
  const Body base = MakeBody(model, model.root_link(), -1);
  const SurfaceSamples base_samples = BodySamples(base, cad.icp, options.samples.max_icp_samples);
  if (base_samples.points.empty()) {
    return Status::Error("robot fit: the base link '" +
                         model.links()[static_cast<size_t>(base.link)].name +
                         "' has no mesh to register");
  }
  std::vector<Pose> roughs;  // best first
  {
    CorrespondenceSearch search(&scans, weights);
    const ScanVisibility visibility(&scans);
    const JointSweep sweep(&search.lattice(), &visibility);
    const Status rough =
        RoughBasePoses(model, scans, base, cad, sweep, options, say, result, &roughs);
    if (!rough.ok()) return not_ok(rough.message());
  }

  // Extension: the rest on the rays near the rough base poses only. The
  // fit has its own copy when it crops or registers the stations (in place,
  // below: the searches built on `work` before are stale after).
  const bool align_stations = options.stations.align && scans.scans.size() > 1;
  ScanSet own;
  if (options.crop.enabled) {
    std::vector<Eigen::Vector3d> centers;
    for (const Pose& T : roughs) centers.push_back(T.translation());
    own = CropToRays(scans, centers, ModelReach(model) + options.crop.margin);
    say("crop: " + std::to_string(own.TotalValid()) + " of " + std::to_string(scans.TotalValid()) +
        " points on rays near the rough base poses");
  } else if (align_stations) {
    own = scans;
  }
  const ScanSet& work = options.crop.enabled || align_stations ? own : scans;
  CorrespondenceSearch search(&work, weights);
  const ScanVisibility visibility(&work);
  WeightedIcp icp(&work, &search, scan_normals, options.residuals);
  const JointSweep sweep(&search.lattice(), &visibility);

  // Sec. 5.1.2 and 5.2-5.3 from each rough base pose kept: the base's
  // precise ICP, then the joints, parents first; the lowest Eq. (9) loss
  // of the whole model wins.
  ChainFitter chain(model, options.chain, options.samples, cad.icp, cad.sweep, &icp, &sweep, say);
  auto fit_from = [&](const Pose& T_rough, WeightedIcp* icp, ChainFitter* chain,
                      Attempt* attempt) -> Status {
    auto stage = std::chrono::steady_clock::now();
    say("base: precise weighted ICP");
    LinkState base_state;
    base_state.T_world_link = T_rough;
    EDGEFIT_RETURN_IF_ERROR(
        icp->Fit(base_samples, LinkMotion::Free(), options.base.icp, &base_state, &attempt->base));
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
  };
  Attempt best;
  EDGEFIT_RETURN_IF_ERROR(fit_from(roughs.front(), &icp, &chain, &best));
  const auto alternatives_start = std::chrono::steady_clock::now();
  for (size_t k = 1; k < roughs.size(); ++k) {
    const double apart = (roughs[k].translation() - roughs.front().translation()).norm();
    if (apart > options.base.hypotheses.instance_separation && !best.base_mismatch) {
      char line[160];
      std::snprintf(line, sizeof(line),
                    "base: alternative rough pose %zu stands %.2f m away: another machine's "
                    "place, not fitted",
                    k, apart);
      say(line);
      continue;
    }
    say("base: the whole chain from alternative rough pose " + std::to_string(k));
    Attempt other;
    EDGEFIT_RETURN_IF_ERROR(fit_from(roughs[k], &icp, &chain, &other));
    char line[240];
    std::snprintf(line, sizeof(line),
                  "base: alternative rough pose %zu: whole model Eq. 9 loss %.1f against %.1f%s", k,
                  other.loss, best.loss, other.loss < best.loss ? ": taken" : "");
    say(line);
    if (other.loss < best.loss) {
      best = std::move(other);
      result->base_rough.T_world_base = roughs[k];
    }
  }
  result->timings.alternatives = Since(alternatives_start);
  if (best.base_mismatch) {
    const BodyQuality b = Quality(model, base, base_samples, best.base, options.quality);
    result->T_world_base = best.T_world_base;
    result->bodies.push_back(b);
    char line[300];
    std::snprintf(line, sizeof(line),
                  "%s does not match the scan: %.0f%% of its visible samples are inliers of "
                  "its precise ICP from every rough pose, RMS %.2f mm (the fit stops below "
                  "%.0f%%)",
                  b.link.c_str(), 100.0 * b.inlier_share, 1e3 * b.rms,
                  100.0 * options.min_base_inlier_share);
    return not_ok(line);
  }
  result->T_world_base = best.T_world_base;
  result->bodies.push_back(Quality(model, base, base_samples, best.base, options.quality));
  Status resolved = model.ResolveDependentJoints(&best.q);
  result->q = best.q;

  // Extensions: the stations registered to the fitted model, then the whole
  // chain at once on them, and its covariance.
  const CellMask mixed = RefinementMissingCells(work, options, say, result);
  if (align_stations) {
    EDGEFIT_RETURN_IF_ERROR(
        AlignStationsStage(model, &own, mixed, &search, weights, cad, options, say, result));
  }
  const ScanSet& final_scans = work;
  CorrespondenceSearch final_search(&final_scans, weights);
  WeightedIcp final_icp(&final_scans, &final_search, scan_normals, options.residuals);
  CellMask covered;
  EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, final_scans, mixed, &final_search, weights, cad,
                                           options, say, result, &covered));
  const bool stations_moved =
      LargestCorrection(result->stations) > options.stations.refit_correction;
  const bool covered_link = CoveringsHideALink(result->coverings, options.refinement.coverings);
  const ScanVisibility final_visibility(&final_scans);
  const JointSweep final_sweep(&final_search.lattice(), &final_visibility);
  if (!stations_moved && !covered_link) {
    // Every joint's basin at the final values, then the verdict of every
    // body alone there.
    ChainFitter final_chain(model, options.chain, options.samples, cad.icp, cad.sweep, &final_icp,
                            &final_sweep, say);
    EDGEFIT_RETURN_IF_ERROR(RefineIntoBestBasins(model, &final_chain, final_scans, mixed,
                                                 &final_search, weights, cad, options, say, result,
                                                 &best.records, &covered));
    EDGEFIT_RETURN_IF_ERROR(
        JudgeQuality(model, &final_icp, cad, best.records, resolved, options, result));
    result->timings.total = Since(start);
    return Status::Ok();
  }

  // Extension: the sequential fit chose every joint's basin on stations
  // that did not agree, or with coverings hiding much of a link: the chain
  // again, from the base, on the aligned stations without the coverings;
  // then the refinement and the verdict there.
  say(std::string("chain: ") +
      (stations_moved ? "the stations moved" : "coverings hide much of a link") +
      ": fitting the chain again on the aligned stations without the coverings");
  ScanSet clean_scans = final_scans;
  for (size_t s = 0; s < covered.size(); ++s) {  // empty without covering rounds
    for (size_t i = 0; i < covered[s].size(); ++i) {
      if (covered[s][i]) clean_scans.scans[s].SetMissing(i);
    }
  }
  CorrespondenceSearch clean_search(&clean_scans, weights);
  const ScanVisibility clean_visibility(&clean_scans);
  WeightedIcp clean_icp(&clean_scans, &clean_search, scan_normals, options.residuals);
  const JointSweep clean_sweep(&clean_search.lattice(), &clean_visibility);
  ChainFitter clean_chain(model, options.chain, options.samples, cad.icp, cad.sweep, &clean_icp,
                          &clean_sweep, say);
  clean_chain.set_covered_scan(&final_sweep);
  const std::vector<double> q_with_coverings = result->q;
  Attempt refit;
  EDGEFIT_RETURN_IF_ERROR(fit_from(result->T_world_base, &clean_icp, &clean_chain, &refit));
  result->T_world_base = refit.T_world_base;
  result->bodies.front() = Quality(model, base, base_samples, refit.base, options.quality);
  resolved = model.ResolveDependentJoints(&refit.q);
  result->q = refit.q;
  const CoveringSummary first_coverings = result->coverings;
  const CellMask clean_mixed = RefinementMissingCells(clean_scans, options, say, result);
  EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, clean_scans, clean_mixed, &clean_search, weights,
                                           cad, options, say, result, &covered));
  result->coverings = first_coverings;  // the cells left out of the second pass
  EDGEFIT_RETURN_IF_ERROR(RefineIntoBestBasins(model, &clean_chain, clean_scans, clean_mixed,
                                               &clean_search, weights, cad, options, say, result,
                                               &refit.records, &covered));
  EDGEFIT_RETURN_IF_ERROR(
      JudgeQuality(model, &clean_icp, cad, refit.records, resolved, options, result));
  if (covered_link) MarkBasinChanges(model, clean_chain, q_with_coverings, options, say, result);
  result->timings.total = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
