#include "edgefit/pipeline/noise_scale.h"

#include <algorithm>

namespace edgefit {
namespace {

// A threshold grown by k, and at least `floor`.
double Grow(double value, double k, double floor) { return std::max(value * k, floor); }

// The final gate (the ICP's occlusion tolerance too: a sample counts as
// hidden when the scan lies nearer by more than it) grows with the noise,
// to at least `floor` (3 sigma: a tolerance inside the noise drops the
// samples whose points fell nearer, a bias away from the sensor); the first
// gate covers the error of the estimate the stage starts from, which does
// not grow: only to stay above the final one.
void Scale(double k, double floor, WeightedIcpOptions* icp) {
  icp->final_gate = Grow(icp->final_gate, k, floor);
  icp->correspondence.max_distance = std::max(icp->correspondence.max_distance, icp->final_gate);
  icp->quality_reach *= k;
  icp->quality_max_view_gap *= k;
}

void Scale(double k, double floor, JointSweepOptions* sweep) {
  sweep->tau_dist *= k;
  sweep->max_distance = std::max(sweep->max_distance, 2.0 * sweep->tau_dist);
  sweep->occluded_loss *= k;
  sweep->visibility_tolerance = Grow(sweep->visibility_tolerance, k, floor);
  sweep->max_view_gap *= k;
}

}  // namespace

double NoiseScaleFor(double sigma, const NoiseOptions& options) {
  if (!options.scale || !(sigma > 0.0)) return 1.0;
  return std::clamp(sigma / options.reference_sigma, 1.0, options.max_scale);
}

FitOptions ScaledToNoise(const FitOptions& options, double sigma) {
  FitOptions scaled = options;
  const double k = NoiseScaleFor(sigma, options.noise);
  if (k == 1.0) {
    // The pair sweep is for noisy scans: on laser scans it changed no joint
    // measured (three virtual scans of the bundled robot) and made the scans
    // without the robot take 1.7 times as long to be said not ok.
    scaled.chain.pair_sweep_step = 0.0;
    return scaled;
  }
  const double floor = 3.0 * sigma;
  Scale(k, floor, &scaled.base.icp);
  ChainOptions& chain = scaled.chain;
  Scale(k, floor, &chain.sweep);
  Scale(k, floor, &chain.joint_icp);
  Scale(k, floor, &chain.subtree_icp);
  chain.flat_sweep_loss *= k;
  chain.ambiguity_check_loss *= k;
  chain.ambiguity_mean_loss *= k;
  chain.explained_distance *= k;
  chain.pinning_mean_loss *= k;
  RefinementOptions& refinement = scaled.refinement;
  Scale(k, floor, &refinement.chain.icp);
  refinement.chain.visibility_tolerance = Grow(refinement.chain.visibility_tolerance, k, floor);
  // The sensor's error is correlated over the surface (a depth camera's
  // matcher smooths it: 0.8 mm from pixel to pixel on the ZED 2i frames,
  // 11 mm against the CAD): in the covariance each patch deviates as a
  // whole, as the CAD's own deviation does (NoiseOptions::patch_deviation).
  refinement.chain.cad_deviation =
      std::max(refinement.chain.cad_deviation, options.noise.patch_deviation * sigma);
  // No coverings: a jacket lies 2-5 mm off its link, inside a depth
  // camera's noise, and what stands out of the CAD over an area there is the
  // camera's correlated error. Left out, it is a one-sided trim of the noise
  // that leans the links into the points kept (inside the CAD): on the real
  // ZED 2i frames, coverings at k times the laser's offsets took 20-40 % of
  // the matched points, and at 2 and 4 sigma still a fifth of a link; with
  // none, the bases and most joints were nearer on all 5 frames
  // (benchmarks/results/2026-11-29-no-coverings-on-noisy-scans.md).
  refinement.coverings.rounds = 0;
  StationAlignmentOptions& stations = scaled.stations;
  stations.final_gate = Grow(stations.final_gate, k, floor);
  stations.max_distance = std::max(stations.max_distance, stations.final_gate);
  stations.huber_scale *= k;
  stations.point_sigma *= k;
  // The verdict's RMS limit keeps its ratio to the joint ICP's final gate
  // (3 mm of 5 on laser scans): a bound that only samples spread across
  // the whole gate reach (uniform within it: 0.58 of the gate). At k times
  // alone it would be the noise itself (k x 3 mm = sigma), which the RMS of
  // a right link's matches within 3 sigma reaches wherever that link is
  // noisier than where the base meets the scan: on depth frames the noise
  // grows with range squared, and 28 of the 35 links said not to match in
  // 22 fits of virtual and 15 of real depth frames had 82-100 % of their
  // samples within the gate, at 1.0-1.6 times sigma (median 1.08)
  // (benchmarks/results/2026-11-30-floor-and-rms-limit.md).
  scaled.quality.max_rms *= scaled.chain.joint_icp.final_gate / options.chain.joint_icp.final_gate;
  scaled.quality.observability.surface_tolerance *= k;
  scaled.mixed_pixels.tolerance *= k;
  return scaled;
}

}  // namespace edgefit
