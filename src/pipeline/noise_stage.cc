// Extension for noisy sensors: the noise where the fit meets the model, and
// the thresholds scaled to it (stages.h, noise_scale.h).
#include <cstdio>

#include "edgefit/pipeline/noise_scale.h"
#include "stages.h"

namespace edgefit {

Status MeasureNoise(const SurfaceSamples& base_samples, const Pose& T_rough,
                    const FitOptions& options, WeightedIcp* icp, const ProgressFn& say,
                    FitResult* result, FitOptions* scaled) {
  *scaled = options;
  if (!options.noise.scale) return Status::Ok();
  WeightedIcpOptions wide = options.base.icp;
  wide.correspondence.max_distance = options.noise.gate;
  wide.final_gate = options.noise.gate;  // fixed: the noise is not cut off
  wide.point_to_plane = true;
  // Distances to the samples' tangent planes (WeightedIcpOptions::
  // quality_reach > the gate): the scan's spacing does not count in them.
  wide.quality_reach = 2.0 * options.noise.gate;
  LinkState state;
  state.T_world_link = T_rough;
  WeightedIcpSummary summary;
  EDGEFIT_RETURN_IF_ERROR(icp->Fit(base_samples, LinkMotion::Free(), wide, &state, &summary));
  // 1.4826 x the median absolute distance: sigma of a normal distribution.
  result->noise_sigma = 1.4826 * summary.median_distance;
  result->noise_scale = NoiseScaleFor(result->noise_sigma, options.noise);
  *scaled = ScaledToNoise(options, result->noise_sigma);
  char line[200];
  std::snprintf(line, sizeof(line),
                "noise: %.1f mm where the base meets the scan (%zu samples); distance thresholds "
                "x %.2f",
                1e3 * result->noise_sigma, summary.inliers, result->noise_scale);
  say(line);
  return Status::Ok();
}

}  // namespace edgefit
