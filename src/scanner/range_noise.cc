#include "edgefit/scanner/range_noise.h"

#include <algorithm>
#include <cmath>

namespace edgefit {

double RangeNoiseOptions::NoiseFactor(double signal) const {
  if (!signal_model) return 1.0;
  if (!(signal > 0.0)) return max_factor;
  return std::min(max_factor, 1.0 / std::sqrt(signal));
}

double RangeNoiseOptions::DropoutProbability(double signal) const {
  if (!signal_model) return 0.0;
  if (signal <= dropout_signal_none) return 1.0;
  if (signal >= dropout_signal_full) return 0.0;
  return (dropout_signal_full - signal) / (dropout_signal_full - dropout_signal_none);
}

bool RangeNoiseOptions::IsValid(std::string* error) const {
  if (!(reference_reflectance > 0.0 && reference_reflectance <= 1.0)) {
    *error = "range noise: reference_reflectance must be in (0, 1]";
  } else if (!(max_factor >= 1.0)) {
    *error = "range noise: max_factor must be >= 1";
  } else if (!(dropout_signal_none >= 0.0 && dropout_signal_none < dropout_signal_full)) {
    *error = "range noise: need 0 <= dropout_signal_none < dropout_signal_full";
  } else {
    return true;
  }
  return false;
}

}  // namespace edgefit
