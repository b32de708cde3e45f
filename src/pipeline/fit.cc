// Fit(): the paper's pipeline, stage by stage (fit.h).
#include "edgefit/pipeline/fit.h"

#include <glog/logging.h>

#include <chrono>
#include <cstdio>
#include <utility>
#include <vector>

#include "solvers/registration/station_alignment.h"
#include "stages.h"

namespace edgefit {
namespace {

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

// The CAD samples of every link: dense for the ICP stages, sparse for the
// sweeps, and per body for the whole-chain stages.
CadSamples SampleCad(const KinematicModel& model, const FitOptions& options) {
  SamplingOptions sampling;
  sampling.seed = options.seed;
  CadSamples cad;
  sampling.spacing = options.samples.icp_spacing;
  cad.icp = SampleModelSurfaces(model, sampling);
  sampling.spacing = options.samples.sweep_spacing;
  cad.sweep = SampleModelSurfaces(model, sampling);
  cad.chain = ChainSamples(model, cad, options);
  cad.chain_settling = SettlingSamples(cad.chain, options);
  return cad;
}

// Why a fit stops when the base matched from no rough pose.
std::string BaseMismatchMessage(const BodyQuality& b, const FitOptions& options) {
  char line[300];
  std::snprintf(line, sizeof(line),
                "%s does not match the scan: %.0f%% of its visible samples are inliers of its "
                "precise ICP from every rough pose, RMS %.2f mm (the fit stops below %.0f%%)",
                b.link.c_str(), 100.0 * b.inlier_share, 1e3 * b.rms,
                100.0 * options.min_base_inlier_share);
  return line;
}

// FitOptions::known_joints: the model with those joints held (frozen), the
// fit of the others, then the result read against the original model: the
// held joints at their values, each with the verdict "given".
Status FitWithKnownJoints(const KinematicModel& model, const ScanSet& scans,
                          const FitOptions& options, const ProgressFn& progress,
                          FitResult* result) {
  KinematicModel frozen;
  EDGEFIT_RETURN_IF_ERROR(FreezeJoints(model, options.known_joints, &frozen));
  FitOptions rest = options;
  rest.known_joints.clear();
  EDGEFIT_RETURN_IF_ERROR(Fit(frozen, scans, rest, progress, result));
  SetKnownJoints(model, options.known_joints, &result->q);
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const Joint& joint = model.joints()[j];
    if (!joint.IsIndependent() || frozen.joints()[j].IsMoving()) continue;
    BodyQuality given;
    given.joint = joint.name;
    given.link = model.links()[static_cast<size_t>(joint.child_link)].name;
    given.verdict = JointVerdict::kGiven;
    given.ok = true;
    given.sweep_value = result->q[j];
    result->bodies.push_back(given);
  }
  return Status::Ok();
}

}  // namespace

Status Fit(const KinematicModel& model, const ScanSet& written_scans, const FitOptions& options,
           const ProgressFn& progress, FitResult* result) {
  CHECK(result != nullptr);
  if (!options.known_joints.empty()) {
    return FitWithKnownJoints(model, written_scans, options, progress, result);
  }
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
                    const EdgeDetectionResult& edges, const FitOptions& given_options,
                    const ProgressFn& progress, FitResult* result) {
  FitOptions options = given_options;  // scaled to the noise below
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
  const CellWeights* weights = options.uniform_weights ? nullptr : &edges.w_edge;
  const auto* normals = edges.normals.empty() ? nullptr : &edges.normals;
  const CadSamples cad = SampleCad(model, options);
  const Body base = MakeBody(model, model.root_link(), -1);
  const SurfaceSamples base_samples = BodySamples(base, cad.icp, options.samples.max_icp_samples);
  if (base_samples.points.empty()) {
    return Status::Error("robot fit: the base link '" +
                         model.links()[static_cast<size_t>(base.link)].name +
                         "' has no mesh to register");
  }

  // Sec. 5.1.1 / 6.1: the base body's rough poses, best first.
  std::vector<RoughPose> roughs;
  {
    ScanTools tools(&scans, weights, normals, options.residuals);
    const Status rough =
        RoughBasePoses(model, scans, base, cad, &tools, options, say, result, &roughs);
    if (!rough.ok()) return not_ok(rough.message());
  }

  // Extension: the rest on the rays near the rough base poses only. The
  // fit has its own copy when it crops or registers the stations (in place,
  // below: the tools built on `work` before are stale after).
  const bool align_stations = options.stations.align && scans.scans.size() > 1;
  ScanSet own;
  if (options.crop.enabled) {
    std::vector<Eigen::Vector3d> centers;
    for (const RoughPose& r : roughs) centers.push_back(r.T_world_base.translation());
    own = CropToRays(scans, centers, ModelReach(model) + options.crop.margin);
    say("crop: " + std::to_string(own.TotalValid()) + " of " + std::to_string(scans.TotalValid()) +
        " points on rays near the rough base poses");
  } else if (align_stations) {
    own = scans;
  }
  const ScanSet& work = options.crop.enabled || align_stations ? own : scans;

  // Sec. 5.1.2 and 5.2-5.3 from each rough base pose kept: the base's
  // precise ICP, then the joints, parents first; the lowest Eq. (9) loss
  // of the whole model wins.
  ChainAttempt best;
  {
    ScanTools tools(&work, weights, normals, options.residuals);
    // Extension for noisy sensors: every distance threshold scaled to the
    // noise where the base meets the scan (noise_scale.h).
    FitOptions scaled;
    EDGEFIT_RETURN_IF_ERROR(MeasureNoise(base_samples, roughs.front().T_world_base, options,
                                         &tools.icp, say, result, &scaled));
    options = scaled;
    ChainFitter chain(model, options.chain, options.samples, cad.icp, cad.sweep, &tools.icp,
                      &tools.sweep, say);
    EDGEFIT_RETURN_IF_ERROR(FitChainFromRoughPoses(model, base, base_samples, roughs, options,
                                                   &tools.icp, &chain, say, result, &best));
  }
  result->T_world_base = best.T_world_base;
  result->bodies.push_back(Quality(model, base, base_samples, best.base, options.quality));
  if (best.base_mismatch) return not_ok(BaseMismatchMessage(result->bodies.front(), options));
  const Status resolved = model.ResolveDependentJoints(&best.q);
  result->q = best.q;

  // Extensions: the stations registered to the fitted model, then the whole
  // chain at once on them, and its covariance.
  CellMask mixed = RefinementMissingCells(work, options, say, result);
  if (align_stations) {
    CorrespondenceSearch search(&own, weights);
    EDGEFIT_RETURN_IF_ERROR(
        AlignStationsStage(model, &own, mixed, &search, weights, cad, options, say, result));
  }
  ScanTools final_tools(&work, weights, normals, options.residuals);
  CellMask covered;
  const bool stations_moved =
      LargestCorrection(result->stations) > options.stations.refit_correction;
  if (!stations_moved) {
    EDGEFIT_RETURN_IF_ERROR(RefineWholeChain(model, work, mixed, &final_tools.search, weights,
                                             cad, options, say, result, &covered));
  } else if (options.refinement.chain.refine && options.refinement.coverings.rounds > 0) {
    // The chain is fitted again on the aligned stations, below: all it
    // takes from here is the coverings at the estimate the stations were
    // last registered at.
    EDGEFIT_RETURN_IF_ERROR(
        CoveringsAtTheEstimate(model, work, &final_tools.search, cad, options, say, result,
                               &covered));
  }
  const bool covered_link = CoveringsHideALink(result->coverings, options.refinement.coverings);
  if (stations_moved || covered_link) {
    say(std::string("chain: ") +
        (stations_moved ? "the stations moved" : "coverings hide much of a link") +
        ": fitting the chain again on the aligned stations without the coverings");
    mixed = CellMask();  // the second pass finds its own (a byte per cell)
    EDGEFIT_RETURN_IF_ERROR(RefitWithoutCoverings(model, work, std::move(covered), final_tools,
                                                  base, base_samples, cad, weights, normals,
                                                  covered_link, options, say, result));
  } else {
    // Every joint's basin at the final values, then the verdict of every
    // body alone there.
    ChainFitter chain(model, options.chain, options.samples, cad.icp, cad.sweep, &final_tools.icp,
                      &final_tools.sweep, say);
    EDGEFIT_RETURN_IF_ERROR(RefineIntoBestBasins(model, &chain, work, mixed, &final_tools.search,
                                                 weights, cad, options, say, result, &best.records,
                                                 &covered));
    EDGEFIT_RETURN_IF_ERROR(
        JudgeQuality(model, &final_tools.icp, cad, best.records, resolved, options, result));
  }
  result->timings.total = Since(start);
  return Status::Ok();
}

}  // namespace edgefit
