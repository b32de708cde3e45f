// The median of a sample, found in place (the upper one of an even count).
#ifndef EDGEFIT_CORE_MEDIAN_H_
#define EDGEFIT_CORE_MEDIAN_H_

#include <algorithm>
#include <cstddef>
#include <vector>

namespace edgefit {

// Reorders *values; it must not be empty.
inline double MedianInPlace(std::vector<double>* values) {
  const size_t mid = values->size() / 2;
  std::nth_element(values->begin(), values->begin() + static_cast<std::ptrdiff_t>(mid),
                   values->end());
  return (*values)[mid];
}

}  // namespace edgefit

#endif  // EDGEFIT_CORE_MEDIAN_H_
