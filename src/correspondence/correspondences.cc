#include "edgefit/correspondence/correspondences.h"

#include <cmath>

namespace edgefit {

bool CorrespondenceOptions::IsValid(std::string* error) const {
  if (!(max_distance > 0.0) || !std::isfinite(max_distance)) {
    if (error) *error = "max_distance must be positive and finite [m]";
    return false;
  }
  if (window < 0 || window > 64) {
    if (error) *error = "window must be in [0, 64] cells";
    return false;
  }
  return true;
}

}  // namespace edgefit
