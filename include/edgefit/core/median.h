// The median of a sample, found in place (the upper one of an even count).
#ifndef EDGEFIT_CORE_MEDIAN_H_
#define EDGEFIT_CORE_MEDIAN_H_

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace edgefit {

// Reorders *values; NaN when it is empty.
inline double MedianInPlace(std::vector<double>* values) {
  if (values->empty()) return std::numeric_limits<double>::quiet_NaN();
  const size_t mid = values->size() / 2;
  std::nth_element(values->begin(), values->begin() + static_cast<std::ptrdiff_t>(mid),
                   values->end());
  return (*values)[mid];
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_MEDIAN_H_
