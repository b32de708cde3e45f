#include "edgefit/scanner/station_residuals.h"

#include <cmath>

#include "edgefit/core/random_unit.h"

namespace edgefit {

bool StationResidualOptions::IsValid(std::string* error) const {
  if (!(translation_min >= 0.0 && translation_min <= translation_max && translation_max < 1.0)) {
    *error = "station residuals: translation must satisfy 0 <= min <= max < 1 m";
  } else if (!(rotation_min >= 0.0 && rotation_min <= rotation_max && rotation_max < 0.1)) {
    *error = "station residuals: rotation must satisfy 0 <= min <= max < 0.1 rad";
  } else {
    return true;
  }
  return false;
}

std::vector<Pose> PerturbStationPoses(const std::vector<Pose>& T_world_true,
                                      const StationResidualOptions& options) {
  std::vector<Pose> written = T_world_true;
  if (!options.enabled) return written;
  for (size_t i = 0; i < written.size(); ++i) {
    SplitMix64 rng = SplitMix64::Stream(options.seed, i + 1);
    const double angle = rng.Uniform(options.rotation_min, options.rotation_max);
    const Eigen::Vector3d axis = RandomUnitVector(&rng);
    const double length = rng.Uniform(options.translation_min, options.translation_max);
    const Eigen::Vector3d shift = length * RandomUnitVector(&rng);
    written[i].linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * T_world_true[i].linear();
    written[i].translation() = T_world_true[i].translation() + shift;
  }
  return written;
}

}  // namespace edgefit
