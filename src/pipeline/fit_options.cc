#include "edgefit/pipeline/fit_options.h"

namespace edgefit {

WeightedIcpOptions BaseOptions::DefaultIcp() {
  WeightedIcpOptions options;
  options.correspondence.max_distance = 0.05;  // the rough stage's error
  options.max_iterations = 60;
  options.point_to_plane = true;
  return options;
}

bool BaseOptions::IsValid(std::string* error) const {
  if (!up.allFinite()) {
    *error = "up must be finite";
    return false;
  }
  return floor.IsValid(error) && cross_sections.IsValid(error) && arm_tips.IsValid(error) &&
         hypotheses.IsValid(error) && icp.IsValid(error) && up_estimation.IsValid(error);
}

bool QualityOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!(min_inlier_share >= 0.0 && min_inlier_share <= 1.0)) {
    return fail("min_inlier_share must be in [0, 1]");
  }
  if (!(max_rms > 0.0)) return fail("max_rms must be > 0");
  if (!(min_base_seen_share >= 0.0 && min_base_seen_share <= 1.0)) {
    return fail("min_base_seen_share must be in [0, 1]");
  }
  return observability.IsValid(error);
}

bool NoiseOptions::IsValid(std::string* error) const {
  if (!(reference_sigma > 0.0)) *error = "noise: reference_sigma must be > 0";
  else if (!(max_scale >= 1.0)) *error = "noise: max_scale must be >= 1";
  else if (!(gate > 0.0)) *error = "noise: gate must be > 0";
  else if (!(patch_deviation >= 0.0)) *error = "noise: patch_deviation must be >= 0";
  else return true;
  return false;
}

bool FitOptions::IsValid(std::string* error) const {
  if (!(min_base_inlier_share >= 0.0 && min_base_inlier_share <= 1.0)) {
    if (error != nullptr) *error = "min_base_inlier_share must be in [0, 1]";
    return false;
  }
  return mixed_pixels.IsValid(error) && crop.IsValid(error) && edges.IsValid(error) &&
         stations.IsValid(error) && residuals.IsValid(error) && samples.IsValid(error) &&
         base.IsValid(error) && chain.IsValid(error) && refinement.chain.IsValid(error) &&
         refinement.coverings.IsValid(error) && quality.IsValid(error) && noise.IsValid(error) &&
         base.voting.IsValid(error);
}

}  // namespace edgefit
