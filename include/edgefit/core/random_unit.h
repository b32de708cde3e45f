// A uniformly distributed unit vector from the seeded generator (z uniform
// in [-1, 1], azimuth uniform: Archimedes' hat-box theorem).
#ifndef EDGEFIT_CORE_RANDOM_UNIT_H_
#define EDGEFIT_CORE_RANDOM_UNIT_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "edgefit/core/split_mix64.h"

namespace edgefit {

inline Eigen::Vector3d RandomUnitVector(SplitMix64* rng) {
  const double z = rng->Uniform(-1.0, 1.0);
  const double a = rng->Uniform(0.0, 2.0 * M_PI);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(a), s * std::sin(a), z};
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_RANDOM_UNIT_H_
